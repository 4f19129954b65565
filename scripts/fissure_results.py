"""Reading a Fissure results.h5 for the plot scripts (docs/output.md).

Shared by plot_blocks.py and plot_final_state.py; needs numpy only (the
caller opens the file with h5py).
"""
import numpy as np

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
