#!/usr/bin/python3
"""Plot of the dda_scaling benchmark (docs/performance.md, section dda_scaling).

    benchmarks/dda_scaling/plot.py [results.csv]

Reads the CSV written by bench_dda_scaling and writes scaling.png beside it:
left, the CPU time per accepted step against the number of blocks (dynamic
and static settling, the first steps from rest) with the default solver
(auto), its split into contact detection and linear solve, block-Jacobi pcg
for comparison, the static wall's steps 201-240 (auto) and the 20 ms / 0.5
s targets; right, the CPU time per
simulated millisecond (time per step / mean dt), which is what a user waits
for.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("results.csv")
    all_rows = [r for r in csv.DictReader(path.open()) if r["status"] != "failed"]
    rows = [r for r in all_rows if r["phase"] == "transient"]
    later = sorted((r for r in all_rows if r["phase"] == "later" and r["mode"] == "static"
                    and r["solver"] == "auto"), key=lambda r: int(r["blocks"]))
    whole = sorted((r for r in all_rows if r["phase"] == "whole"), key=lambda r: int(r["blocks"]))
    fig, (ax, aw) = plt.subplots(1, 2, figsize=(10, 4.2))
    for i, mode in enumerate(["dynamic", "static"]):
        pick = lambda solver: sorted(  # noqa: E731
            (r for r in rows if r["mode"] == mode and r["solver"] == solver),
            key=lambda r: int(r["blocks"]))
        pcg = pick("pcg")
        if pcg:
            ax.loglog([int(r["blocks"]) for r in pcg], [1e3 * float(r["cpu_s"]) for r in pcg],
                      "x-", color=f"C{i}", lw=1, alpha=0.5, label=f"{mode}: pcg total")
        sel = pick("auto")
        if not sel:
            continue
        n = np.array([int(r["blocks"]) for r in sel])
        col = lambda key: np.array([float(r[key]) for r in sel])  # noqa: E731
        cpu, dt = col("cpu_s"), col("mean_dt_s")
        ax.loglog(n, 1e3 * cpu, "o-", color=f"C{i}", lw=2, label=f"{mode}: total")
        ax.loglog(n, 1e3 * col("solve_s"), "s--", color=f"C{i}", lw=1, label=f"{mode}: solve")
        ax.loglog(n, 1e3 * col("detection_s"), "^:", color=f"C{i}", lw=1,
                  label=f"{mode}: contact detection")
        aw.loglog(n, cpu / (1e3 * dt), "o-", color=f"C{i}", lw=2,
                  label=f"{mode} (mean dt {1e3 * dt.mean():.2f} ms)")
    if later:
        ax.loglog([int(r["blocks"]) for r in later], [1e3 * float(r["cpu_s"]) for r in later],
                  "D-", color="C2", lw=2, label="static, steps 201-240: total")
    if whole:
        ax.loglog([int(r["blocks"]) for r in whole], [1e3 * float(r["cpu_s"]) for r in whole],
                  "P-", color="C3", lw=2, label="static, mean of steps 1-300")
    ax.loglog([1000, 10000], [20, 500], "k*", ms=12, label="targets")
    ax.set_xlabel("blocks")
    ax.set_ylabel("CPU ms per accepted step")
    ax.set_title("cost per step (auto; 40 steps from rest unless noted)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    aw.set_xlabel("blocks")
    aw.set_ylabel("CPU s per simulated ms")
    aw.set_title("cost per simulated time")
    aw.grid(True, which="both", alpha=0.3)
    aw.legend(fontsize=8)
    fig.suptitle("DDA: staggered brick walls settling under gravity (one core)")
    fig.tight_layout()
    out = path.with_name("scaling.png")
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
