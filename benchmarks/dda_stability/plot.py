#!/usr/bin/python3
"""Plot of the DDA stability sweep (docs/performance.md, section dda_stability).

    benchmarks/dda_stability/plot.py [results.csv [results_undamped.csv]]

Reads the CSV written by bench_dda_stability and writes stability.png beside
it: per case (dt x penalty, grouped by dt) the displacement (log scale, its
limit dashed), the wall time, and the open-close iterations per accepted step
with the number of step cuts written on the bars. With the slope sweep run
without vibration damping (results_undamped.csv beside it, when present) a
third row shows that sweep's displacements: the creep the damping removed.
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).parent))
from table import PENALTIES, read  # noqa: E402  (same CSV reader as the markdown table)

COLORS = dict(zip(PENALTIES, ("tab:cyan", "tab:blue", "tab:orange", "tab:red", "tab:gray")))


def grouped(ax, rows, scene, value, log=False, labels=None):
    sub = [r for r in rows if r["scene"] == scene]
    dts = sorted({r["dt"] for r in sub})
    width = 0.8 / len(PENALTIES)
    for k, pen in enumerate(PENALTIES):
        cases = [next((r for r in sub if r["dt"] == dt and r["penalty_factor"] == pen), None)
                 for dt in dts]
        x = np.arange(len(dts)) + (k - (len(PENALTIES) - 1) / 2) * width
        y = [value(r) if r else np.nan for r in cases]
        bars = ax.bar(x, y, width, color=COLORS[pen], label=f"penalty {pen}")
        if labels:
            for bar, r in zip(bars, cases):
                if r and labels(r):
                    ax.annotate(labels(r), (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                                ha="center", va="bottom", fontsize=5, rotation=90)
    ax.set_xticks(np.arange(len(dts)), [f"{dt:.0e} s" for dt in dts])
    ax.set_xlabel("time step dt", fontsize=8)
    if log:
        ax.set_yscale("log")
    ax.grid(True, axis="y", alpha=0.3)


def displacement_panel(ax, rows, scene, title):
    grouped(ax, rows, scene, lambda r: r["displacement"], log=True)
    limit = next(r["limit"] for r in rows if r["scene"] == scene)
    ax.axhline(limit, color="k", linestyle="--", linewidth=0.8)
    ax.set_ylabel("displacement (m)")
    ax.set_title(title, fontsize=9)


def main():
    here = Path(__file__).parent
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else here / "results.csv"
    undamped_path = Path(sys.argv[2]) if len(sys.argv) > 2 else path.with_name(
        "results_undamped.csv")
    rows = read(path)
    undamped = read(undamped_path) if undamped_path.exists() else []
    fig, axes = plt.subplots(3 if undamped else 2, 3, figsize=(15, 11 if undamped else 7.5))
    for row, scene in enumerate(("wall", "slope")):
        what = ("10 x 10 brick wall, top brick (1 s; 0.1 s at 1e-5 s, 0.01 s at 1e-6 s), "
                "limit 1 mm" if scene == "wall"
                else "block on a 22.6 deg slope, phi = 30 deg, 2 s, limit 0.1 mm")
        displacement_panel(axes[row, 0], rows, scene, what)
        grouped(axes[row, 1], rows, scene, lambda r: r["wall_seconds"], log=True)
        axes[row, 1].set_ylabel("wall time (s, single run)")
        grouped(axes[row, 2], rows, scene, lambda r: r["its_per_step"],
                labels=lambda r: f"{r['time_step_cuts']} cuts" if r["time_step_cuts"] else "")
        axes[row, 2].set_ylabel("open-close iterations per step")
    if undamped:
        displacement_panel(axes[2, 0], undamped, "slope",
                           "the same slope without vibration damping (damping_ratio 0)")
        grouped(axes[2, 1], undamped, "slope", lambda r: r["open_contacts"])
        axes[2, 1].set_ylabel("open contacts at the end (of 2)")
        axes[2, 1].set_title("slope without vibration damping", fontsize=9)
        grouped(axes[2, 2], undamped, "slope", lambda r: r["kinetic_energy"], log=True)
        axes[2, 2].set_ylabel("kinetic energy at the end (J)")
        axes[2, 2].set_title("slope without vibration damping", fontsize=9)
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
