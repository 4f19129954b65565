#!/usr/bin/env python3
"""Draw the blocks of one output frame of a Fissure run (docs/output.md).

    scripts/plot_blocks.py OUTDIR [--frame -1] [--field umag] [--scale 1] [-o blocks.png]

Reads OUTDIR/results.h5 and draws the block outlines (holes included) of the
chosen frame, filled with colour from a field, plus the contacts coloured by
state (open, sliding, locked) when the frame has any. Writes OUTDIR/blocks.png
(or OUTDIR/NAME) and prints the path.

Fields: ux, uy, umag (displacement magnitude, the default), vx, vy, speed
(on vertices, interpolated over each triangle); sxx, syy, sxy, block_id (one
value per block).
"""
import argparse
import sys
from pathlib import Path

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")  # files only, no display needed
    import matplotlib.pyplot as plt
    import matplotlib.tri as mtri
    import numpy as np
    from matplotlib.collections import LineCollection
    from mpl_toolkits.axes_grid1 import make_axes_locatable
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_blocks.py: {e.name} is missing; install python3-numpy, python3-h5py and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fissure_results import complete_frames, outline_segments  # noqa: E402

# name: (dataset, component or None, "node" | "cell", label)
FIELDS = {
    "ux": ("displacement", 0, "node", "ux (m)"),
    "uy": ("displacement", 1, "node", "uy (m)"),
    "umag": ("displacement", None, "node", "|u| (m)"),
    "vx": ("velocity", 0, "node", "vx (m/s)"),
    "vy": ("velocity", 1, "node", "vy (m/s)"),
    "speed": ("velocity", None, "node", "|v| (m/s)"),
    "sxx": ("sxx", None, "cell", "sxx (Pa, tension +)"),
    "syy": ("syy", None, "cell", "syy (Pa, tension +)"),
    "sxy": ("sxy", None, "cell", "sxy (Pa)"),
    "block_id": ("block_id", None, "cell", "block index"),
}
CONTACT_STATES = ((0, "open", "tab:gray"), (1, "sliding", "tab:orange"), (2, "locked", "tab:red"))


def field_values(group, field):
    dataset, component, _, _ = FIELDS[field]
    values = group[dataset][...]
    if values.ndim == 1:
        return values.astype(float)
    if component is None:
        return np.linalg.norm(values[:, :2], axis=1)
    return values[:, component]


def exaggerate_contacts(points, group, block_vertex_offsets, scale):
    """Moves each contact point with the vertex of its block_i nearest to it,
    so that it stays on the drawn (exaggerated) geometry."""
    x = group["vertices"][...]
    u = group["displacement"][...][:, :2]
    moved = points.copy()
    for c, (p, b) in enumerate(zip(points, group["contacts/block_i"][...])):
        first, last = block_vertex_offsets[b], block_vertex_offsets[b + 1]
        nearest = first + np.argmin(np.linalg.norm(x[first:last] - p, axis=1))
        moved[c] = p + (scale - 1) * u[nearest]
    return moved


def draw(h5, t, group, field, scale, png):
    mesh = h5["mesh"]
    x0 = mesh["initial_vertices"][...]
    x = x0 + scale * (group["vertices"][...] - x0)
    triangles = mesh["triangles"][...]
    block_vertex_offsets = mesh["block_vertex_offsets"][...]
    values = field_values(group, field)
    _, _, centre, label = FIELDS[field]

    size = np.ptp(x, axis=0) if len(x) else np.ones(2)
    aspect = size[1] / size[0] if size[0] > 0 else 1.0
    fig, ax = plt.subplots(figsize=(9, float(np.clip(8 * aspect, 2.5, 9)) + 1))
    if len(triangles):
        tri = mtri.Triangulation(x[:, 0], x[:, 1], triangles)
        if centre == "node":
            image = ax.tripcolor(tri, values, shading="gouraud", cmap="viridis")
        else:
            image = ax.tripcolor(tri, facecolors=values, shading="flat", cmap="viridis")
        # A colour bar exactly as tall as the (equal-aspect) drawing.
        cax = make_axes_locatable(ax).append_axes("right", size="3%", pad=0.1)
        fig.colorbar(image, cax=cax, label=label)

    # Outlines: every loop of every block (outer loops and holes).
    ax.add_collection(LineCollection(outline_segments(mesh, x), colors="black", linewidths=0.8))

    if "contacts" in group:
        points = group["contacts/points"][...]
        states = group["contacts/state"][...]
        if scale != 1:
            points = exaggerate_contacts(points, group, block_vertex_offsets, scale)
        for state, name, colour in CONTACT_STATES:
            chosen = states == state
            if chosen.any():
                ax.scatter(points[chosen, 0], points[chosen, 1], s=14, color=colour, zorder=3,
                           label=f"{name} ({chosen.sum()})")
        # Below the x label, clear of the drawing.
        ax.legend(title="contacts", fontsize="small", loc="upper center",
                  bbox_to_anchor=(0.5, 0), borderaxespad=3.8, ncol=3)

    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    exaggerated = f", displacements x {scale:g}" if scale != 1 else ""
    ax.set_title(f"{group.name}  t = {t:.6g} s{exaggerated}")
    fig.savefig(png, dpi=130, bbox_inches="tight")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", type=Path, help="output folder of a run")
    parser.add_argument("--frame", type=int, default=-1,
                        help="frame index, negative counts from the end (default: -1, the last)")
    parser.add_argument("--field", default="umag", choices=sorted(FIELDS),
                        help="colour field (default: umag, the displacement magnitude)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="displacement exaggeration for drawing (default: 1)")
    parser.add_argument("-o", "--output", default="blocks.png",
                        help="PNG file name inside OUTDIR (default: blocks.png)")
    args = parser.parse_args()

    h5_file = args.outdir / "results.h5"
    if not h5_file.is_file():
        sys.exit(f"plot_blocks.py: {h5_file} not found")
    with h5py.File(h5_file, "r") as h5:
        frames = complete_frames(h5)
        if not frames:
            sys.exit(f"plot_blocks.py: {h5_file} has no complete frame")
        if not -len(frames) <= args.frame < len(frames):
            sys.exit(f"plot_blocks.py: --frame {args.frame} is out of range; "
                     f"{h5_file} has {len(frames)} frames")
        t, group = frames[args.frame]
        png = args.outdir / args.output
        draw(h5, t, group, args.field, args.scale, png)
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
