#!/usr/bin/env python3
"""Check that ParaView reads a Fissure results.xdmf correctly (docs/output.md).

    pvpython scripts/check_xdmf_paraview.py OUTDIR_OR_XDMF [--all-frames]

For developers who have ParaView (Debian: python3-paraview, or pvpython).
Opens results.xdmf with both XDMF 3 readers of ParaView ("Xdmf3 Reader" and
"Xdmf3 Reader (Top Level Partition)") and compares what ParaView sees with
results.h5 read by h5py: the time steps, the vertex positions, the arrays
displacement and velocity (vertices), sxx, syy, sxy and block_id (triangles),
the triangle connectivity, every contact array, and the fracture network: its
nodes and segments (from /mesh/fractures, or the frame's own), the network's
cell arrays and, with flow, the node pressure (and head) and the segment
apertures and fluxes. Checks the first, a middle and the last frame (every
frame with --all-frames) and prints the values of one vertex, one triangle,
one contact and one fracture node so that a reader can see them.

Exit status: 0 all checks passed (or ParaView is not installed: skipped, with a
message), 1 a check failed, 2 usage error.

A sample: the unit tests leave one in the build folder,
    pvpython scripts/check_xdmf_paraview.py build/test-output/results_writer/FourFrames
"""
import argparse
import sys
from pathlib import Path

try:
    from paraview import servermanager
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("check_xdmf_paraview.py: ParaView's Python modules are not importable "
          "(install python3-paraview, or run with pvpython); check skipped")
    sys.exit(0)
try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"check_xdmf_paraview.py: {e.name} is missing (install python3-h5py); check skipped")
    sys.exit(0)

READERS = (("Xdmf3ReaderT", "Xdmf3 Reader"), ("Xdmf3ReaderS", "Xdmf3 Reader (Top Level Partition)"))
NODE_ARRAYS = ("displacement", "velocity")
CELL_ARRAYS = ("sxx", "syy", "sxy", "block_id")
CONTACT_ARRAYS = ("normal", "state", "gap", "normal_force", "shear_force", "block_i", "block_j")
NETWORK_ARRAYS = ("aperture", "length", "set", "fracture", "component", "dead_end")  # cells
FLOW_NODE_ARRAYS = ("pressure", "head")  # head only with gravity
FLOW_CELL_ARRAYS = ("aperture_a", "aperture_b", "aperture_mean", "flux")


class Checker:
    def __init__(self):
        self.failures = 0

    def equal(self, what, seen, expected):
        seen, expected = np.asarray(seen), np.asarray(expected)
        if seen.shape != expected.shape or not np.array_equal(seen, expected):
            self.failures += 1
            print(f"  FAIL {what}: ParaView {seen.shape} differs from results.h5 {expected.shape}")
            return False
        return True

    def true(self, what, condition):
        if not condition:
            self.failures += 1
            print(f"  FAIL {what}")
        return condition


def leaves(data):
    """Every leaf data set of a (possibly composite) data object."""
    if not data.IsA("vtkCompositeDataSet"):
        return [data]
    out = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        out.append(it.GetCurrentDataObject())
        it.GoToNextItem()
    return out


def array(data, centre, name):
    attributes = data.GetPointData() if centre == "node" else data.GetCellData()
    a = attributes.GetArray(name)
    return None if a is None else vtk_to_numpy(a)


def reference(h5_file):
    """Complete frames (time, group name) in time order, and the mesh."""
    h5 = h5py.File(h5_file, "r")
    frames = sorted((float(g.attrs["time"]), g.name) for g in h5["frames"].values()
                    if "time" in g.attrs)
    return h5, frames


def kind(data):
    """blocks, contacts or fractures: the three grids of a frame (docs/output.md)."""
    if data.GetPointData().GetArray("displacement") is not None:
        return "blocks"
    if data.GetPointData().GetArray("normal_force") is not None:
        return "contacts"
    return "fractures"


def check_fractures(c, fractures, h5, g):
    """The frame's fracture grid against /mesh/fractures and the frame's fractures/."""
    own = "fractures/nodes" in g
    if not own and "mesh/fractures" not in h5:
        c.true("no fractures grid without a fracture network", not fractures)
        return
    if not c.true("exactly one fractures grid", len(fractures) == 1):
        return
    f = fractures[0]
    geometry = g["fractures"] if own else h5["mesh/fractures"]
    nodes, segments = geometry["nodes"][...], geometry["segments"][...]
    c.true(f"{len(nodes)} fracture nodes and {len(segments)} segments",
           f.GetNumberOfPoints() == len(nodes) and f.GetNumberOfCells() == len(segments))
    c.equal("fracture node positions", vtk_to_numpy(f.GetPoints().GetData())[:, :2], nodes)
    for cell in (0, len(segments) - 1):
        ids = f.GetCell(cell).GetPointIds()
        c.equal(f"nodes of segment {cell}", [ids.GetId(i) for i in range(ids.GetNumberOfIds())],
                segments[cell])
    if not own:  # the network's own fields belong to /mesh/fractures
        for name in NETWORK_ARRAYS:
            a = array(f, "cell", name)
            if c.true(f"segment array {name} present", a is not None):
                c.equal(f"segment array {name}", a, h5["mesh/fractures/" + name][...])
    if "fractures/pressure" not in g:
        c.true("no flow arrays in a frame without flow", array(f, "node", "pressure") is None)
        return
    for centre, names in (("node", FLOW_NODE_ARRAYS), ("cell", FLOW_CELL_ARRAYS)):
        for name in names:
            if name not in g["fractures"]:
                continue
            a = array(f, centre, name)
            if c.true(f"fracture {centre} array {name} present", a is not None):
                c.equal(f"fracture {centre} array {name}", a, g["fractures/" + name][...])


def check_frame(c, leaf_sets, h5, group_name, n_triangles):
    g = h5[group_name]
    blocks = [d for d in leaf_sets if kind(d) == "blocks"]
    contacts = [d for d in leaf_sets if kind(d) == "contacts"]
    check_fractures(c, [d for d in leaf_sets if kind(d) == "fractures"], h5, g)
    if not c.true("exactly one blocks grid", len(blocks) == 1):
        return
    b = blocks[0]
    points = vtk_to_numpy(b.GetPoints().GetData())
    c.equal("vertex positions", points[:, :2], g["vertices"][...])
    c.true("z = 0 at every vertex", not np.any(points[:, 2]))
    c.true(f"{n_triangles} triangles", b.GetNumberOfCells() == n_triangles)
    triangles = h5["mesh/triangles"][...]
    for cell in (0, n_triangles - 1):
        ids = b.GetCell(cell).GetPointIds()
        c.equal(f"connectivity of triangle {cell}",
                [ids.GetId(i) for i in range(ids.GetNumberOfIds())], triangles[cell])
    for name in NODE_ARRAYS:
        a = array(b, "node", name)
        if c.true(f"vertex array {name} present", a is not None):
            c.equal(f"vertex array {name}", a, g[name][...])
    for name in CELL_ARRAYS:
        a = array(b, "cell", name)
        if c.true(f"triangle array {name} present", a is not None):
            c.equal(f"triangle array {name}", a, g[name][...])

    if "contacts" not in g:
        c.true("no contacts grid in a frame without contacts", not contacts)
        return
    if not c.true("exactly one contacts grid", len(contacts) == 1):
        return
    k = contacts[0]
    n = g["contacts/gap"].shape[0]
    c.true(f"{n} contact points and cells", k.GetNumberOfPoints() == n and k.GetNumberOfCells() == n)
    c.equal("contact points", vtk_to_numpy(k.GetPoints().GetData())[:, :2], g["contacts/points"][...])
    for name in CONTACT_ARRAYS:
        a = array(k, "node", name)
        if c.true(f"contact array {name} present", a is not None):
            c.equal(f"contact array {name}", a, g["contacts/" + name][...])


def show_sample(leaf_sets, time):
    """Prints one vertex, one triangle, one contact and one fracture node as ParaView sees them."""
    for d in leaf_sets:
        if kind(d) == "blocks":
            v = d.GetNumberOfPoints() // 3
            u = array(d, "node", "displacement")[v]
            vel = array(d, "node", "velocity")[v]
            print(f"  t = {time:g}: vertex {v} at {tuple(d.GetPoint(v)[:2])}, displacement "
                  f"{tuple(u)}, velocity {tuple(vel)}")
            print(f"  t = {time:g}: triangle 0 sxx = {array(d, 'cell', 'sxx')[0]:.10g}, "
                  f"syy = {array(d, 'cell', 'syy')[0]:.10g}, block_id = {array(d, 'cell', 'block_id')[0]}")
        elif kind(d) == "contacts":
            print(f"  t = {time:g}: contact 0 at {tuple(d.GetPoint(0)[:2])}, state "
                  f"{array(d, 'node', 'state')[0]}, normal_force {array(d, 'node', 'normal_force')[0]:g}")
        elif d.GetNumberOfPoints() > 0:
            p = array(d, "node", "pressure")
            print(f"  t = {time:g}: fracture node 0 at {tuple(d.GetPoint(0)[:2])}"
                  + ("" if p is None else f", pressure {p[0]:g} Pa"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("path", type=Path, help="output folder or its results.xdmf")
    parser.add_argument("--all-frames", action="store_true", help="check every frame")
    args = parser.parse_args()
    xdmf = args.path / "results.xdmf" if args.path.is_dir() else args.path
    # The XDMF reader resolves "results.h5" against the folder of the path it
    # is given, which must therefore be absolute.
    xdmf = xdmf.resolve()
    h5_file = xdmf.parent / "results.h5"
    if not xdmf.is_file() or not h5_file.is_file():
        print(f"check_xdmf_paraview.py: need {xdmf} and {h5_file}")
        return 2

    h5, frames = reference(h5_file)
    times = [t for t, _ in frames]
    n_triangles = h5["mesh/triangles"].shape[0]
    chosen = range(len(frames)) if args.all_frames else sorted({0, len(frames) // 2, len(frames) - 1})
    c = Checker()
    for proxy, label in READERS:
        print(f"{label} ({proxy}): {xdmf}")
        reader = getattr(simple, proxy)(FileName=[str(xdmf)])
        steps = reader.TimestepValues
        seen = list(steps) if hasattr(steps, "__len__") else [steps]
        c.equal("time steps", seen, times)
        print(f"  {len(seen)} time steps from {seen[0] if seen else '-'} to {seen[-1] if seen else '-'} s")
        for i in chosen if frames else []:
            t, group_name = frames[i]
            reader.UpdatePipeline(t)
            leaf_sets = leaves(servermanager.Fetch(reader))
            check_frame(c, leaf_sets, h5, group_name, n_triangles)
            if i == chosen[-1]:
                show_sample(leaf_sets, t)
        simple.Delete(reader)
    if c.failures:
        print(f"check_xdmf_paraview.py: {c.failures} check(s) FAILED")
        return 1
    print(f"check_xdmf_paraview.py: all checks passed ({len(chosen)} of {len(frames)} frames, "
          f"{len(READERS)} readers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
