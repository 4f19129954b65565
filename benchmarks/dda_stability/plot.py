#!/usr/bin/python3
"""Plot of the DDA stability sweep (docs/performance.md, section dda_stability).

    benchmarks/dda_stability/plot.py [results.csv]

Reads the CSV written by bench_dda_stability and writes stability.png beside
it: per case (dt x penalty, grouped by dt) the displacement (its limit in the panel
title), the wall time, and the open-close iterations per accepted step with
the number of step cuts written on the bars.
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).parent))
from table import read  # noqa: E402  (same CSV reader as the markdown table)

PENALTIES = ("5E", "50E", "500E", "auto")
COLORS = dict(zip(PENALTIES, ("tab:blue", "tab:orange", "tab:red", "tab:gray")))


def grouped(ax, rows, scene, value, log=False, labels=None):
    sub = [r for r in rows if r["scene"] == scene]
    dts = sorted({r["dt"] for r in sub})
    width = 0.8 / len(PENALTIES)
    for k, pen in enumerate(PENALTIES):
        cases = [next((r for r in sub if r["dt"] == dt and r["penalty_factor"] == pen), None)
                 for dt in dts]
        x = np.arange(len(dts)) + (k - 1.5) * width
        y = [value(r) if r else np.nan for r in cases]
        bars = ax.bar(x, y, width, color=COLORS[pen], label=f"penalty {pen}")
        if labels:
            for bar, r in zip(bars, cases):
                if r and labels(r):
                    ax.annotate(labels(r), (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                                ha="center", va="bottom", fontsize=6)
    ax.set_xticks(np.arange(len(dts)), [f"dt = {dt:.0e} s" for dt in dts])
    if log:
        ax.set_yscale("log")
    ax.grid(True, axis="y", alpha=0.3)


def main():
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("results.csv")
    rows = read(path)
    fig, axes = plt.subplots(2, 3, figsize=(14, 7.5))
    for row, scene in enumerate(("wall", "slope")):
        what = ("10 x 10 brick wall, top brick, limit 1 mm in 1 s" if scene == "wall"
                else "block on a 22.6 deg slope, phi = 30 deg, limit 0.1 mm in 2 s")
        grouped(axes[row, 0], rows, scene, lambda r: 1e6 * r["displacement"])
        axes[row, 0].set_ylabel("displacement (micrometres)")
        axes[row, 0].set_title(what, fontsize=9)
        grouped(axes[row, 1], rows, scene, lambda r: r["wall_seconds"], log=True)
        axes[row, 1].set_ylabel("wall time (s, single run)")
        grouped(axes[row, 2], rows, scene, lambda r: r["its_per_step"],
                labels=lambda r: f"{r['time_step_cuts']} cuts" if r["time_step_cuts"] else "")
        axes[row, 2].set_ylabel("open-close iterations per step")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(PENALTIES), fontsize=9)
    passed = sum(r["passed"] for r in rows)
    fig.suptitle(f"DDA stability sweep: {passed} of {len(rows)} cases pass; stiff penalties cost "
                 "step cuts and open-close iterations")
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    out = path.with_name("stability.png")
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
