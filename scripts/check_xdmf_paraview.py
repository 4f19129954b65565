#!/usr/bin/env python3
"""Check that ParaView reads a Fissure results.xdmf correctly (docs/output.md).

    pvpython scripts/check_xdmf_paraview.py OUTDIR_OR_XDMF [--all-frames]

For developers who have ParaView (Debian: paraview, or python3-paraview).
Opens results.xdmf with both XDMF 3 readers of ParaView ("Xdmf3 Reader" and
"Xdmf3 Reader (Top Level Partition)") and compares what ParaView sees with
results.h5 read by h5py, for every grid of a frame (blocks, contacts,
fractures, thermal, fracture_fluid, continuum):

  * every grid: its points against its Geometry dataset (z = 0), its cells
    against its Topology dataset (count, first and last cell), and every
    attribute against the dataset its Attribute names;
  * that the index names the right datasets: the blocks on the frame's
    vertices with displacement, velocity, sxx, syy, sxy and block_id; the
    contacts; the fracture network (from /mesh/fractures, or the frame's own)
    with its cell arrays and, with flow, the node pressure (and head) and
    the segment apertures and fluxes; the continuum with its named stress
    components (sxx, syy, sxy, szz; srr, szz, srz, shoop when axisymmetric),
    excess pressure and, with heat, temperature change;
  * the time steps; and in the XML, that the Temporal collection notes the
    unit of time (s) and the scene's, and that every attribute carries its
    unit (<Information Name="unit">).

Checks the first, a middle and the last frame (every frame with
--all-frames) and prints one value of each grid so that a reader can see
them.

Exit status: 0 all checks passed, 1 a check failed, 2 usage error, 77
ParaView's Python modules (or h5py) are not importable: skipped, with a
message (ctest's SKIP_RETURN_CODE).

A sample: the unit tests leave one in the build folder,
    pvpython scripts/check_xdmf_paraview.py build/test-output/results_writer/FourFrames
"""
import argparse
import math
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

SKIPPED = 77
try:
    from paraview import servermanager
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
except ImportError:
    print("check_xdmf_paraview.py: ParaView's Python modules are not importable "
          "(install paraview, or run with pvpython); check skipped")
    sys.exit(SKIPPED)
try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"check_xdmf_paraview.py: {e.name} is missing (install python3-h5py); check skipped")
    sys.exit(SKIPPED)

READERS = (("Xdmf3ReaderT", "Xdmf3 Reader"), ("Xdmf3ReaderS", "Xdmf3 Reader (Top Level Partition)"))
BLOCK_ARRAYS = (("node", "displacement"), ("node", "velocity"), ("cell", "sxx"), ("cell", "syy"),
                ("cell", "sxy"), ("cell", "block_id"))
CONTACT_ARRAYS = ("normal", "state", "gap", "normal_force", "shear_force", "block_i", "block_j")
NETWORK_ARRAYS = ("aperture", "length", "set", "fracture", "component", "dead_end")  # cells
FLOW_NODE_ARRAYS = ("pressure", "head")  # head only with gravity
FLOW_CELL_ARRAYS = ("aperture_a", "aperture_b", "aperture_mean", "flux")
CONTINUUM_STRESSES = {False: ("sxx", "syy", "sxy", "szz"), True: ("srr", "szz", "srz", "shoop")}


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


# --- the index, as XML --------------------------------------------------------

class Grid:
    """A grid of a frame as results.xdmf describes it: its name, the
    datasets of its topology and geometry, and its attributes (name ->
    (centre, dataset, unit))."""

    def __init__(self, element):
        self.name = element.get("Name")
        self.topology = dataset_of(element.find("Topology"))
        self.geometry = dataset_of(element.find("Geometry"))
        self.attributes = {}
        for a in element.findall("Attribute"):
            units = [i.get("Value") for i in a.findall("Information") if i.get("Name") == "unit"]
            self.attributes[a.get("Name")] = (a.get("Center", "Node").lower(), dataset_of(a),
                                              units[0] if units else None)


def dataset_of(element):
    """The HDF5 path of an element's DataItem ("results.h5:/frames/..." -> "/frames/...")."""
    item = element.find("DataItem") if element is not None else None
    return item.text.strip().split(":", 1)[-1] if item is not None and item.text else None


def read_index(c, xdmf):
    """{time: [Grid]} of every frame, and checks of the notes on units."""
    root = ElementTree.parse(xdmf).getroot()
    temporal = root.find("Domain/Grid")
    if not c.true("a Temporal collection", temporal is not None
                  and temporal.get("CollectionType") == "Temporal"):
        return {}
    info = {i.get("Name"): i.get("Value") for i in temporal.findall("Information")}
    c.true("the Temporal collection notes time_unit s", info.get("time_unit") == "s")
    c.true("the Temporal collection notes the scene's unit of time",
           bool(info.get("scene_time_unit")) and float(info.get("scene_time_unit_seconds", "nan")) > 0)
    frames = {}
    for frame in temporal.findall("Grid"):
        time = frame.find("Time")
        grids = [Grid(g) for g in frame.findall("Grid")]
        for g in grids:
            for name, (_, _, unit) in g.attributes.items():
                c.true(f"attribute {g.name}/{name} has a unit", bool(unit))
        frames[float(time.get("Value"))] = grids
    print(f"  index: {len(frames)} frames; time in s, scene's unit {info.get('scene_time_unit')}")
    return frames


# --- what ParaView sees -------------------------------------------------------

def leaves(data):
    """Every leaf data set of a (possibly composite) data object, in order."""
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


def cell_ids(data, cell):
    ids = data.GetCell(cell).GetPointIds()
    return [ids.GetId(i) for i in range(ids.GetNumberOfIds())]


def check_grid(c, data, grid, h5):
    """A grid against the datasets its XDMF description names."""
    where = f"{grid.name}:"
    points = vtk_to_numpy(data.GetPoints().GetData()) if data.GetNumberOfPoints() else np.zeros((0, 3))
    xy = h5[grid.geometry][...]
    c.equal(f"{where} point positions", points[:, :2], xy)
    c.true(f"{where} z = 0 at every point", not np.any(points[:, 2]))
    cells = h5[grid.topology][...]
    if c.true(f"{where} {len(cells)} cells", data.GetNumberOfCells() == len(cells)) and len(cells):
        for cell in (0, len(cells) - 1):
            c.equal(f"{where} points of cell {cell}", cell_ids(data, cell),
                    np.atleast_1d(cells[cell]))
    for name, (centre, dataset, _) in grid.attributes.items():
        a = array(data, centre, name)
        if c.true(f"{where} {centre} array {name} present", a is not None):
            c.equal(f"{where} {centre} array {name}", a, h5[dataset][...])


def check_blocks(c, grids, h5, g):
    if h5["mesh/triangles"].shape[0] == 0:
        c.true("no blocks grid without blocks", "blocks" not in grids)
        return
    if not c.true("a blocks grid", "blocks" in grids):
        return
    b = grids["blocks"]
    c.true("blocks on the frame's vertices", b.geometry == g.name + "/vertices")
    c.true("blocks of /mesh/triangles", b.topology == "/mesh/triangles")
    for centre, name in BLOCK_ARRAYS:
        c.true(f"blocks: {name} of the frame", b.attributes.get(name, (None, None))[:2]
               == (centre, f"{g.name}/{name}"))


def check_contacts(c, grids, g):
    if "contacts" not in g:
        c.true("no contacts grid in a frame without contacts", "contacts" not in grids)
        return
    if not c.true("a contacts grid", "contacts" in grids):
        return
    k = grids["contacts"]
    c.true("contacts at contacts/points", k.geometry == g.name + "/contacts/points")
    for name in CONTACT_ARRAYS:
        c.true(f"contacts: {name} of the frame",
               k.attributes.get(name, (None, None))[1] == f"{g.name}/contacts/{name}")


def check_fractures(c, grids, h5, g):
    own = "fractures/nodes" in g
    if not own and "mesh/fractures" not in h5:
        c.true("no fractures grid without a fracture network", "fractures" not in grids)
        return
    if not c.true("a fractures grid", "fractures" in grids):
        return
    f = grids["fractures"]
    geometry = (g.name + "/fractures") if own else "/mesh/fractures"
    c.true(f"fractures on {geometry}", f.geometry == geometry + "/nodes"
           and f.topology == geometry + "/segments")
    if not own:  # the network's own fields belong to /mesh/fractures
        for name in NETWORK_ARRAYS:
            c.true(f"fractures: {name} of /mesh/fractures",
                   f.attributes.get(name, (None, None))[1] == "/mesh/fractures/" + name)
    flow = g.get("fractures")
    if flow is None or "pressure" not in flow:
        c.true("no flow arrays in a frame without flow", "pressure" not in f.attributes)
        return
    for centre, names in (("node", FLOW_NODE_ARRAYS), ("cell", FLOW_CELL_ARRAYS)):
        for name in names:
            if name in flow:
                c.true(f"fractures: {name} of the frame", f.attributes.get(name, (None, None))[:2]
                       == (centre, f"{g.name}/fractures/{name}"))


def check_continuum(c, grids, g):
    if "continuum" not in g:
        c.true("no continuum grid without a continuum", "continuum" not in grids)
        return
    if not c.true("a continuum grid", "continuum" in grids):
        return
    k, at = grids["continuum"], g.name + "/continuum/"
    axisymmetric = "shoop" in g["continuum"]
    names = ["displacement", "pressure", "excess_pressure", *CONTINUUM_STRESSES[axisymmetric],
             "darcy_flux"]
    if "temperature_change" in g["continuum"]:
        names += ["temperature", "temperature_change"]
    for name in names:
        c.true(f"continuum: {name} of the frame",
               k.attributes.get(name, (None, None))[1] == at + name)


def check_frame(c, leaf_sets, grids, h5, group_name):
    g = h5[group_name]
    if not c.true(f"{len(grids)} grids seen, as in the index", len(leaf_sets) == len(grids)):
        return
    by_name = {grid.name: grid for grid in grids}
    for data, grid in zip(leaf_sets, grids):
        check_grid(c, data, grid, h5)
    check_blocks(c, by_name, h5, g)
    check_contacts(c, by_name, g)
    check_fractures(c, by_name, h5, g)
    check_continuum(c, by_name, g)


def composite_names(data):
    """The names the reader gave the leaves ("blocks[2]" -> "blocks"), None for unnamed ones."""
    if not data.IsA("vtkCompositeDataSet"):
        return [None]
    names = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        name = None
        if it.HasCurrentMetaData() and it.GetCurrentMetaData().Has(vtkCompositeDataSet.NAME()):
            name = it.GetCurrentMetaData().Get(vtkCompositeDataSet.NAME()).split("[")[0]
        names.append(name)
        it.GoToNextItem()
    return names


def show_sample(leaf_sets, grids, time):
    """Prints the first point of each grid and one of its values, as ParaView sees them."""
    for data, grid in zip(leaf_sets, grids):
        if data.GetNumberOfPoints() == 0 or not grid.attributes:
            continue
        name, (centre, _, unit) = next(iter(grid.attributes.items()))
        values = array(data, centre, name)
        value = values[0] if values is not None and len(values) else None
        print(f"  t = {time:g} s: {grid.name}: point 0 at {tuple(data.GetPoint(0)[:2])}, "
              f"{centre} 0 {name} = {value} {unit}")


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

    c = Checker()
    print(f"check_xdmf_paraview.py: {xdmf}")
    index = read_index(c, xdmf)
    h5 = h5py.File(h5_file, "r")
    frames = sorted((float(g.attrs["time"]), g.name) for g in h5["frames"].values()
                    if "time" in g.attrs)
    times = [t for t, _ in frames]
    c.equal("the index's times", sorted(index), times)
    chosen = range(len(frames)) if args.all_frames else sorted({0, len(frames) // 2, len(frames) - 1})
    for proxy, label in READERS:
        print(f"{label} ({proxy})")
        reader = getattr(simple, proxy)(FileName=[str(xdmf)])
        steps = reader.TimestepValues
        seen = list(steps) if hasattr(steps, "__len__") else [steps]
        c.equal("time steps", seen, times)
        print(f"  {len(seen)} time steps from {seen[0] if seen else '-'} to "
              f"{seen[-1] if seen else '-'} s")
        for i in chosen if frames else []:
            t, group_name = frames[i]
            grids = next((v for k, v in index.items() if math.isclose(k, t, rel_tol=1e-15,
                                                                       abs_tol=0)), None)
            if not c.true(f"frame at t = {t:g} s in the index", grids is not None):
                continue
            reader.UpdatePipeline(t)
            data = servermanager.Fetch(reader)
            leaf_sets = leaves(data)
            check_frame(c, leaf_sets, grids, h5, group_name)
            if proxy == "Xdmf3ReaderT":  # it names the leaves after the grids
                c.equal("the grids' names", composite_names(data), [g.name for g in grids])
            if i == chosen[-1]:
                show_sample(leaf_sets, grids, t)
        simple.Delete(reader)
    if c.failures:
        print(f"check_xdmf_paraview.py: {c.failures} check(s) FAILED")
        return 1
    print(f"check_xdmf_paraview.py: all checks passed ({len(chosen)} of {len(frames)} frames, "
          f"{len(READERS)} readers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
