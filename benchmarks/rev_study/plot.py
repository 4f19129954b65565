#!/usr/bin/python3
"""Plots of benchmarks/rev_study (docs/performance.md "rev_study").

rev_study.png   wall time of the full study: 1 thread, 2 threads, 2 MPI ranks
                of 1 thread. (The study's own figures, docs/img/flow_rev_*.png,
                are drawn by the driver with scripts/plot_rev.py.)
"""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent


def main():
    with open(HERE / "results.csv", newline="") as f:
        data = list(csv.DictReader(f))
    labels = [f"{d['ranks']} rank x {d['threads']} thread" + ("s" if d["threads"] != "1" else "")
              for d in data]
    wall = [float(d["wall_s"]) for d in data]
    fig, ax = plt.subplots(figsize=(6, 3.8))
    bars = ax.bar(range(len(wall)), wall, color=["tab:blue", "tab:green", "tab:purple"][: len(wall)])
    for b, w in zip(bars, wall):
        ax.text(b.get_x() + b.get_width() / 2, w, f"{w:.1f} s", ha="center", va="bottom")
    ax.axhline(60, color="k", ls=":", label="target: 60 s on 2 cores")
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("wall time (s)")
    ax.set_title("REV study: 15 sizes x 10 realizations x 12 rotations", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(HERE / "rev_study.png", dpi=100)
    plt.close(fig)

if __name__ == "__main__":
    main()
