#!/usr/bin/env python3
"""Draw a generated rock mass: blocks and fracture network (docs/rock-mass.md).

    scripts/plot_rock_mass.py OUTDIR [--color set|component|aperture|dead_end]
                              [--no-inner] [--zoom X0 Y0 X1 Y1] [--dpi 150]
                              [-o rock_mass.png]

Reads OUTDIR/results.h5 (written by `fissure mesh` or `fissure run`): the
block outlines from /mesh (fixed blocks shaded darker, holes left open) and
the fracture graph from /mesh/fractures, its segments coloured by joint set
or DFN family (default), by connected component, by aperture or by dead end
(grey: dead ends, black: the backbone). Segments inside a block (dangling ends
that do not separate rock) are drawn dashed, unless --no-inner. Writes
OUTDIR/rock_mass.png (or OUTDIR/NAME) and prints the path.
"""
import argparse
import sys
from pathlib import Path

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")  # files only, no display needed
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.collections import LineCollection, PathCollection
    from matplotlib.path import Path as MplPath
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_rock_mass.py: {e.name} is missing; install python3-numpy, python3-h5py and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")


def block_outlines(mesh):
    """Per block: (outer loop, [holes]) as arrays of points, and the fixed flags."""
    v = mesh["initial_vertices"][()]
    loops = mesh["loop_offsets"][()]
    block_loops = mesh["block_loop_offsets"][()]
    blocks = []
    for b in range(len(block_loops) - 1):
        rings = [v[loops[k]:loops[k + 1]] for k in range(block_loops[b], block_loops[b + 1])]
        blocks.append(rings)
    return blocks, mesh["block_fixed"][()].astype(bool)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", type=Path)
    parser.add_argument("--color", default="set", choices=["set", "component", "aperture", "dead_end"])
    parser.add_argument("--no-inner", action="store_true", help="hide segments inside blocks")
    parser.add_argument("--zoom", type=float, nargs=4, metavar=("X0", "Y0", "X1", "Y1"))
    parser.add_argument("--dpi", type=int, default=150, help="resolution of the 10 x 7 in figure")
    parser.add_argument("-o", "--output", default="rock_mass.png")
    args = parser.parse_args()

    path = args.outdir / "results.h5"
    if not path.exists():
        sys.exit(f"plot_rock_mass.py: {path} not found (run `fissure mesh SCENE.yaml -o {args.outdir}`)")
    with h5py.File(path, "r") as h5:
        if "mesh" not in h5:
            sys.exit(f"plot_rock_mass.py: {path} has no /mesh")
        mesh = h5["mesh"]
        blocks, fixed = block_outlines(mesh)
        fr = mesh["fractures"] if "fractures" in mesh else None
        if fr is not None:
            nodes = fr["nodes"][()]
            seg = fr["segments"][()]
            fields = {k: fr[k][()] for k in ("set", "component", "aperture", "dead_end",
                                              "left_block", "right_block")}
            set_names = [s.decode() if isinstance(s, bytes) else s
                         for s in fr["set_names"][()]] if "set_names" in fr else []

    fig, ax = plt.subplots(figsize=(10, 7), dpi=args.dpi)
    # Blocks: one compound path per block, so that holes stay open (a block
    # inside another block's hole shows through); free blocks in light
    # colours that differ between neighbours, fixed blocks grey.
    paths = [MplPath.make_compound_path(*[MplPath(np.vstack([r, r[:1]]), closed=True) for r in rings])
             for rings in blocks]
    pastel = plt.get_cmap("Pastel2")
    faces = [(0.75, 0.75, 0.75, 1.0) if f else pastel((3 * b) % 7) for b, f in enumerate(fixed)]
    ax.add_collection(PathCollection(paths, facecolors=faces, edgecolors="0.3", linewidths=0.5))

    n_segments = 0
    if fr is not None and len(seg) > 0:
        n_segments = len(seg)
        lines = nodes[seg]
        inner = fields["left_block"] == fields["right_block"]
        values = fields[args.color]
        if args.color == "set":
            cmap = plt.get_cmap("tab10")
            colors = [cmap(int(s) % 10) if s >= 0 else (0, 0, 0, 1) for s in values]
            for s in sorted(set(int(x) for x in values)):
                label = set_names[s] if 0 <= s < len(set_names) else ("explicit" if s < 0 else f"set {s}")
                ax.plot([], [], color=cmap(s % 10) if s >= 0 else "k", label=label)
        elif args.color == "component":
            cmap = plt.get_cmap("tab20")
            colors = [cmap(int(c) % 20) for c in values]
        elif args.color == "dead_end":
            colors = ["0.6" if d else "k" for d in values]
            ax.plot([], [], color="k", label="backbone")
            ax.plot([], [], color="0.6", label="dead end")
        else:
            norm = matplotlib.colors.LogNorm(vmin=max(values.min(), 1e-12), vmax=max(values.max(), 1e-12))
            colors = plt.get_cmap("viridis")(norm(values))
            fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax,
                         label="aperture (m)", shrink=0.7)
        colors = np.array([matplotlib.colors.to_rgba(c) for c in colors])
        ax.add_collection(LineCollection(lines[~inner], colors=colors[~inner], linewidths=1.0))
        if not args.no_inner and inner.any():
            ax.add_collection(LineCollection(lines[inner], colors=colors[inner], linewidths=0.8,
                                             linestyles="dashed"))
        if args.color in ("set", "dead_end"):
            ax.legend(loc="upper right", fontsize=8, framealpha=0.9)

    all_points = np.concatenate([r for rings in blocks for r in rings])
    if args.zoom:
        ax.set_xlim(args.zoom[0], args.zoom[2])
        ax.set_ylim(args.zoom[1], args.zoom[3])
    else:
        lo, hi = all_points.min(axis=0), all_points.max(axis=0)
        pad = 0.02 * (hi - lo).max()
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"{len(blocks)} blocks ({int(fixed.sum())} fixed), {n_segments} fracture segments")
    out = args.outdir / args.output
    fig.tight_layout()
    fig.savefig(out)
    print(out)


if __name__ == "__main__":
    main()
