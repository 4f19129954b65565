#!/usr/bin/env python3
"""Plot the input and the response of a shaken DDA run (docs/dda.md section 10).

    scripts/plot_shaking.py OUTDIR [--base NAME] [-o NAME]

Reads OUTDIR/monitors.csv and summary.json. The monitor `--base` (default
`base`: a monitor on a driven block) is the input: its velocity, and the
record's peaks and baseline correction from summary.json
(processes.mechanics.ground_motion) in the title. Every other monitor is the
response: its horizontal velocity, and its displacement relative to the
base (what the ground motion left behind: slip, toppling). Time in the
scene's unit; velocities in m/s, displacements in µm, mm or m by their
size. Writes OUTDIR/shaking.png (or OUTDIR/NAME) and prints the path.
"""
import argparse
import sys
from pathlib import Path

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_shaking.py: {e.name} is missing; install python3-numpy and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fissure_results import run_summary, si_prefix, time_unit  # noqa: E402
from plot_monitors import read_monitors  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("outdir", type=Path)
    p.add_argument("--base", default="base", help="the monitor on the driven base")
    p.add_argument("-o", "--output", default="shaking.png")
    args = p.parse_args()
    t, monitors = read_monitors(args.outdir / "monitors.csv")
    if args.base not in monitors:
        sys.exit(f"plot_shaking.py: no monitor '{args.base}' in {args.outdir / 'monitors.csv'} "
                 f"(monitors: {', '.join(monitors)}); give the base's with --base")
    summary = run_summary(args.outdir)
    unit_name, unit_seconds = time_unit(summary)
    tt = t / unit_seconds
    base = monitors[args.base]
    others = [m for m in monitors if m != args.base]

    fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
    ax = axes[0]
    ax.plot(tt, base["vx"], color="black", lw=1.0, label="vx")
    ax.plot(tt, base["vy"], color="0.5", lw=1.0, label="vy")
    ax.set_ylabel(f"input: {args.base} velocity (m/s)")
    ax.legend(loc="upper right", fontsize=8)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    ax = axes[1]
    for k, m in enumerate(others):
        ax.plot(tt, monitors[m]["vx"], color=colours[k % len(colours)], lw=0.9, label=m)
    ax.set_ylabel("response: vx (m/s)")
    ax.legend(loc="upper right", fontsize=8)
    ax = axes[2]
    relative = {m: np.hypot(monitors[m]["ux"] - base["ux"], monitors[m]["uy"] - base["uy"])
                for m in others}
    factor, unit = si_prefix(np.concatenate(list(relative.values())) if relative else [0], "m")
    for k, m in enumerate(others):
        ax.plot(tt, relative[m] / factor, color=colours[k % len(colours)], lw=1.2, label=m)
    ax.set_ylabel(f"displacement relative to {args.base} ({unit})")
    ax.set_xlabel(f"t ({unit_name})")
    ax.legend(loc="upper left", fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    title = f"{summary.get('scene', args.outdir.name)}: ground motion and response"
    g = summary.get("processes", {}).get("mechanics", {}).get("ground_motion")
    if isinstance(g, dict) and g.get("peak_acceleration"):
        pga = g["peak_acceleration"]
        title += f"\npeak acceleration {pga[0] / 9.80665:.2f} g horizontal, {pga[1] / 9.80665:.2f} g vertical"
        b = g.get("baseline_correction") or {}
        if b.get("applied"):
            title += ", baseline corrected"
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    png = args.outdir / args.output
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
