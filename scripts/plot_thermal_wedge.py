#!/usr/bin/python3
"""The thermally ratcheting wedge (configs/thermal_wedge.yaml; docs/thermal.md
"Examples: the thermally ratcheting wedge").

    scripts/plot_thermal_wedge.py OUTPUT_DIR [--wedge-only OUTPUT_DIR] [-o PNG]

Reads results.h5 of a run of the scene (and, optionally, of the variant in
which only the wedge expands) and draws against time (days): the sliding
block's downslope displacement s = ux cos 25 - uy sin 25 (um, of the block's
centroid) with its value after each full cycle, and the mean temperatures of
the wedge and of the sliding block (area-weighted over their thermal meshes)
with the air's. Prints, per cycle, the permanent slip and the seed's
estimate (1 + nu) alpha_T dT_wedge w / cos 25 from the wedge's mean
temperature swing in that cycle. Writes PNG (default
docs/img/thermal_wedge.png).
"""
import argparse
import math
from pathlib import Path

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The scene's figures (configs/thermal_wedge.yaml).
SLOPE = math.radians(25.0)
NU, ALPHA = 0.184, 1e-5
WEDGE_MEAN_WIDTH = 0.149  # m, between its top (0.180 m) and bottom (0.118 m)
DAY = 86400.0
AIR = (25.0, 10.0, 14 * 3600.0)  # mean, amplitude, time of the peak


def block_index(f, name):
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["mesh/block_names"][:]]
    return names.index(name)


def history(folder):
    """Times (s), downslope displacement of the block's centroid (m) and the
    mean temperatures of the wedge and the block (degC) of every frame."""
    with h5py.File(Path(folder) / "results.h5", "r") as f:
        block, wedge = block_index(f, "block"), block_index(f, "wedge")
        triangles = f["mesh/thermal_triangles"][:]
        owner = f["mesh/thermal_triangle_block"][:]
        offsets = f["mesh/block_vertex_offsets"][:]
        first = f["mesh/initial_vertices"][offsets[block]:offsets[block + 1]]
        rows = []
        for name in sorted(f["frames"].keys()):
            frame = f["frames"][name]
            nodes, temperature = frame["thermal/nodes"][:], frame["thermal/temperature"][:]
            p = nodes[triangles]
            area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) -
                                (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
            mean_t = temperature[triangles].mean(axis=1)

            def block_mean(b):
                on = owner == b
                return float((area[on] * mean_t[on]).sum() / area[on].sum())

            moved = frame["vertices"][offsets[block]:offsets[block + 1]] - first
            u = moved.mean(axis=0)  # the mean vertex displacement: a rigid slip
            s = u[0] * math.cos(SLOPE) - u[1] * math.sin(SLOPE)
            rows.append((frame.attrs["time"], s, block_mean(wedge), block_mean(block)))
    rows.sort()
    return [np.array(c) for c in zip(*rows)]


def per_cycle(t, s, t_wedge, t_block):
    """Per full day: the slip at its end minus at its start (m), the mean
    temperature swings of the wedge and the block (K) and the estimate from
    the wedge's swing (m)."""
    out = []
    for day in range(1, int(t[-1] // DAY + 1e-9) + 1):
        i0 = int(np.argmin(np.abs(t - (day - 1) * DAY)))
        i1 = int(np.argmin(np.abs(t - day * DAY)))
        swing = t_wedge[i0:i1 + 1].max() - t_wedge[i0:i1 + 1].min()
        block_swing = t_block[i0:i1 + 1].max() - t_block[i0:i1 + 1].min()
        estimate = (1 + NU) * ALPHA * swing * WEDGE_MEAN_WIDTH / math.cos(SLOPE)
        out.append((day, s[i1] - s[i0], swing, block_swing, estimate))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output_dir")
    parser.add_argument("--wedge-only", help="output folder of the run where only the wedge expands")
    parser.add_argument("-o", "--output", default="docs/img/thermal_wedge.png")
    args = parser.parse_args()

    runs = [("every block expands", args.output_dir, "C0")]
    if args.wedge_only:
        runs.append(("only the wedge expands", args.wedge_only, "C2"))
    fig, (ax_s, ax_t) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    for label, folder, colour in runs:
        t, s, t_wedge, t_block = history(folder)
        days = t / DAY
        ax_s.plot(days, s * 1e6, color=colour, label=label)
        cycles = per_cycle(t, s, t_wedge, t_block)
        ends = [int(np.argmin(np.abs(t - d * DAY))) for d, *_ in cycles]
        ax_s.plot(days[ends], s[ends] * 1e6, "o", color=colour, ms=4)
        print(f"{label} ({folder}):")
        for day, slip, swing, block_swing, estimate in cycles:
            print(f"  cycle {day}: slip {slip * 1e6:7.2f} um, swings: wedge {swing:5.2f} K, "
                  f"block {block_swing:5.2f} K; estimate {estimate * 1e6:6.2f} um")
        if colour == "C0":
            ax_t.plot(days, t_wedge, color="C3", label="wedge (mean)")
            ax_t.plot(days, t_block, color="C1", label="sliding block (mean)")
            air = AIR[0] + AIR[1] * np.cos(2 * math.pi * (t - AIR[2]) / DAY)
            ax_t.plot(days, air, color="0.6", lw=0.8, ls="--", label="air")
    ax_s.set_ylabel("downslope displacement of the block (um)")
    ax_s.set_title("Thermal wedging-ratcheting (configs/thermal_wedge.yaml); dots: after each day")
    ax_s.legend(loc="upper left")
    ax_s.grid(alpha=0.3)
    ax_t.set_ylabel("temperature (degC)")
    ax_t.set_xlabel("time (days)")
    ax_t.legend(loc="upper left", ncol=3)
    ax_t.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
