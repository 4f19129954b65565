#!/usr/bin/env python3
"""Work against precision of the DDA and the DEM (benchmarks/dda_vs_dem;
docs/performance.md, "DDA and DEM: work against precision").

    benchmarks/dda_vs_dem/plot.py [results.csv]

Reads the CSV of bench_dda_vs_dem and writes work_precision.png beside it:
the error of each run's end state against its method's converged state,
over its CPU time (least of 3), for the brick wall and the jointed slope;
one line per method and mode (and DDA step), points in the order of the
number of steps, the end time or the solve ratio.
"""
import csv
import math
import pathlib
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
FLOOR = 1e-12  # errors below are drawn here on the log axis

STYLE = {"dda": ("tab:blue", "o"), "dem": ("tab:red", "s")}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("parameter", "error", "ratio", "cpu_seconds"):
            r[k] = float(r[k])
    return rows


def label(r):
    if r["method"] == "dda" and r["mode"] == "static":
        return f"DDA static steps of {r['parameter'] * 1e3:g} ms" if r["scene"] == "wall" else "DDA static steps of 10 ms"
    if r["method"] == "dda":
        return "DDA dynamic steps of 1 ms"
    return "DEM solved to a ratio" if r["mode"] == "solved" else "DEM in real time, local damping 0.8"


def main():
    path = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else HERE / "results.csv"
    rows = [r for r in read(path) if not math.isnan(r["error"])]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    for ax, scene, title in zip(axes, ("wall", "slope"),
                                ("brick wall, rigid blocks on equivalent joints",
                                 "jointed slope (configs/)")):
        lines = defaultdict(list)
        for r in rows:
            if r["scene"] == scene:
                lines[label(r)].append(r)
        for k, (name, rs) in enumerate(sorted(lines.items())):
            colour, marker = STYLE[rs[0]["method"]]
            dashes = ["-", "--", ":", "-."][k % 4]
            ax.loglog([r["cpu_seconds"] for r in rs], [max(r["error"], FLOOR) for r in rs],
                      dashes, color=colour, marker=marker, ms=4, label=name)
        ax.set_xlabel("CPU time (s), least of 3")
        ax.set_ylabel("error of the end state against the converged one")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path.with_name("work_precision.png"), dpi=120)


if __name__ == "__main__":
    main()
