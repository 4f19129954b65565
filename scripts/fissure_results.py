"""Reading a Fissure results.h5 and summary.json for the plot scripts
(docs/output.md).

Shared by plot_blocks.py, plot_final_state.py (and its continuum_picture.py)
and plot_monitors.py; needs numpy only (the caller opens the file with h5py).
"""
import json

import numpy as np

# SI prefixes a picture may put on a unit: the one that brings the largest
# magnitude into [1, 1000).
PREFIXES = {"m": ((1e-6, "µm"), (1e-3, "mm"), (1.0, "m"), (1e3, "km")),
            "Pa": ((1.0, "Pa"), (1e3, "kPa"), (1e6, "MPa"), (1e9, "GPa"))}

# The datasets every frame of the blocks has (docs/output.md, /frames/NNNNNN).
FRAME_DATASETS = ("vertices", "displacement", "velocity", "sxx", "syy", "sxy", "block_id")


def complete_frames(h5):
    """(time, group) of every frame, in time order. The writer links a frame
    into /frames only once it is complete; the check guards against files
    from elsewhere (and a file without /mesh or /frames gives none)."""
    if "mesh" not in h5 or "frames" not in h5:
        return []
    frames = []
    for group in h5["frames"].values():
        if "time" in group.attrs and all(d in group for d in FRAME_DATASETS):
            frames.append((float(group.attrs["time"]), group))
    return sorted(frames, key=lambda f: f[0])


def outline_segments(mesh, vertices):
    """Every edge of every vertex loop of the blocks (outer loops and holes),
    as an S x 2 x 2 array for a LineCollection: loop k closes from its last
    vertex back to its first."""
    loops = mesh["loop_offsets"][...]
    ends = np.arange(1, len(vertices) + 1)
    ends[loops[1:] - 1] = loops[:-1]  # the last vertex of a loop joins its first
    return np.stack([vertices, vertices[ends]], axis=1)


def fracture_network(h5, group):
    """(nodes, segments) of the fracture network of a frame: the frame's own
    when its network differs from /mesh/fractures, else the mesh's; None
    without a network."""
    own = group.get("fractures")
    if own is not None and "nodes" in own and "segments" in own:
        return own["nodes"][...], own["segments"][...]
    fixed = h5["mesh"].get("fractures")
    if fixed is not None and "nodes" in fixed and "segments" in fixed:
        return fixed["nodes"][...], fixed["segments"][...]
    return None


def block_rings(mesh, vertices, blocks):
    """Per chosen block, its vertex loops (outer loop first, then the holes)
    as arrays of points."""
    loops = mesh["loop_offsets"][...]
    block_loops = mesh["block_loop_offsets"][...]
    return [[vertices[loops[k]:loops[k + 1]] for k in range(block_loops[b], block_loops[b + 1])]
            for b in blocks]


def si_prefix(values, unit):
    """(factor, unit): the SI prefix that puts the largest magnitude of
    `values` in [1, 1000) for m and Pa (µm .. km, Pa .. GPa; NaN ignored);
    (1, unit) for other units."""
    values = np.asarray(values, dtype=float)
    finite = np.abs(values[np.isfinite(values)])
    largest = float(finite.max()) if finite.size else 0.0
    if unit not in PREFIXES or largest == 0.0:
        return 1.0, unit
    factor, name = PREFIXES[unit][0]
    for f, n in PREFIXES[unit]:
        if largest >= f:
            factor, name = f, n
    return factor, name


def scaled(values, unit):
    """(values, unit) in the SI prefix of si_prefix."""
    factor, name = si_prefix(values, unit)
    return np.asarray(values, dtype=float) / factor, name


def run_summary(outdir):
    """summary.json of the output folder as a dict ({} when it cannot be read)."""
    try:
        return json.loads((outdir / "summary.json").read_text())
    except (OSError, ValueError):
        return {}


def time_unit(summary):
    """(name, seconds): the scene's unit of time, which the pictures use
    (summary.json `time_unit`, the unit time.end was written in); s for an
    older summary without it."""
    unit = summary.get("time_unit") or {}
    name, seconds = unit.get("name"), unit.get("seconds")
    if isinstance(name, str) and isinstance(seconds, (int, float)) and seconds > 0:
        return name, float(seconds)
    return "s", 1.0


def axisymmetric(summary):
    """Whether the run's continuum is axisymmetric (x is the radius r, y the
    axis z): summary.json processes.continuum.geometry."""
    continuum = (summary.get("processes") or {}).get("continuum") or {}
    return continuum.get("geometry") == "axisymmetric"


def point_markers(h5):
    """{kind: [(name, (x, y)), ...]} of /mesh/markers (monitors, wells, heat
    sources, where they are at the start); {} in an older file."""
    markers = {}
    group = h5["mesh"].get("markers") if "mesh" in h5 else None
    for g in (group.values() if group is not None else []):
        kind = g.attrs.get("kind", "")
        kind = kind.decode() if isinstance(kind, bytes) else str(kind)
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in g["names"][...]]
        markers.setdefault(kind, []).extend(zip(names, (tuple(p) for p in g["points"][...])))
    return markers
