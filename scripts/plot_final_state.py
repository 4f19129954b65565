#!/usr/bin/env python3
"""Draw the final state of a Fissure run, as UDEC's plots do (docs/output.md).

    scripts/plot_final_state.py OUTDIR [--field auto] [--fractures auto] [--contacts]
                                [--layout auto] [-o final_state.png]

Reads the last frame of OUTDIR/results.h5 (and OUTDIR/results.xdmf, which
names every grid that carries a temperature) and draws the blocks in their
final position, filled by one field, with thin outlines; where the flow is
on, the fractures on top as lines coloured by the fluid pressure, each as
thick as the flow it carries. The block field, unless --field names one:

  * temperature, where the run has heat (a grid of results.xdmf, other than
    the fractures, with a `temperature` attribute);
  * else the displacement magnitude |u|, where any vertex has moved;
  * else the most compressive principal stress, where any block is stressed;
  * else none (grey blocks: a flow run on rigid blocks).

A continuum run (docs/continuum.md 5) is drawn by continuum_picture.py:
maps of its temperature change and excess pore pressure (or --field, a
comma list: pressure, excess_pressure, temperature, temperature_change,
umag, ux, uy and the stress components), or, for a thin strip, profiles of
every field along it (--layout). Monitors, wells and heat sources are
marked; the time is in the scene's unit (summary.json).

Blocks tied to a continuum around them (a run with both) are drawn together:
the continuum's triangles and the blocks coloured by the same field (the
block fields above, the stresses per block and per triangle) on one colour
scale, displacements in mm and stresses in MPa, the blocks on top with their
outlines; the whole model in one panel and, when the block region is less
than a tenth of the continuum's width, beside it a panel zoomed on the
blocks (their bounding box with half its larger side around it).

Writes OUTDIR/final_state.png (or OUTDIR/NAME) and prints its path. A run
without results.h5 or without a complete frame is not an error: the script
says so and exits with status 0 without a picture (`fissure run` then says
the picture was not made).
"""
import argparse
import math
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")  # files only, no display needed
    import matplotlib.pyplot as plt
    import matplotlib.tri as mtri
    import numpy as np
    from matplotlib.collections import LineCollection, PathCollection
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Rectangle
    from matplotlib.path import Path as MplPath
    from mpl_toolkits.axes_grid1 import make_axes_locatable
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_final_state.py: {e.name} is missing; install python3-numpy, python3-h5py and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")

sys.path.insert(0, str(Path(__file__).resolve().parent))
from continuum_picture import FIELDS as CONTINUUM_FIELDS  # noqa: E402
from continuum_picture import (draw_continuum, has_continuum, is_continuum_frame,  # noqa: E402
                               material_outlines)
from fissure_results import (axisymmetric, block_rings, complete_frames,  # noqa: E402
                             fracture_network, outline_segments, point_markers, run_summary,
                             scaled, time_unit)
from picture_markers import add_markers, moved_monitors  # noqa: E402

BLOCK_FIELDS = ("auto", "temperature", "umag", "vmag", "smin", "smax", "sxx", "syy", "sxy",
                "none")
FRACTURE_FIELDS = ("auto", "pressure", "head", "flux", "aperture", "none")
STRESS_LABELS = {
    "smin": "most compressive principal stress",
    "smax": "least compressive principal stress",
    "sxx": "stress sxx",
    "syy": "stress syy",
    "sxy": "stress sxy",
}
CONTACT_STATES = ((0, "open", "0.35", "o"), (1, "sliding", "tab:red", "x"))


class Field:
    """Values to colour by, where they live ("node" or "cell" of `triangulation`)
    and how to label them."""

    def __init__(self, name, label, unit, values, centre, triangulation, cmap):
        self.name, self.label, self.unit = name, label, unit
        self.values, self.centre = values, centre
        self.triangulation, self.cmap = triangulation, cmap


def readable_time(t, summary):
    """t in the scene's unit of time (summary.json)."""
    name, seconds = time_unit(summary)
    return f"t = {t / seconds:.4g} {name}"


# --- the block field ---------------------------------------------------------

def xdmf_temperature(outdir, h5, t):
    """The temperature grid of the frame at time t from results.xdmf: the first
    Triangle grid (not the fractures, nor a continuum around the blocks) with an
    attribute named temperature.
    None when there is none, or the index cannot be read."""
    try:
        root = ElementTree.parse(outdir / "results.xdmf").getroot()
    except (OSError, ElementTree.ParseError):
        return None

    def dataset(item):  # "results.h5:/frames/000001/x" -> the dataset
        path = item.text.strip().split(":", 1)[-1] if item is not None and item.text else ""
        return h5[path][...] if path in h5 else None

    for collection in root.iter("Grid"):
        time = collection.find("Time")
        if time is None or not math.isclose(float(time.get("Value", "nan")), t, rel_tol=1e-9,
                                            abs_tol=1e-300):
            continue
        for grid in collection.findall("Grid"):
            topology, geometry = grid.find("Topology"), grid.find("Geometry")
            attributes = [a for a in grid.findall("Attribute")
                          if a.get("Name", "").lower() == "temperature"]
            if (grid.get("Name") in ("fractures", "continuum") or not attributes
                    or topology is None or topology.get("TopologyType") != "Triangle"
                    or geometry is None):
                continue
            triangles = dataset(topology.find("DataItem"))
            points = dataset(geometry.find("DataItem"))
            values = dataset(attributes[0].find("DataItem"))
            if triangles is None or points is None or values is None:
                continue
            centre = "node" if attributes[0].get("Center", "Node") == "Node" else "cell"
            if len(values) != (len(points) if centre == "node" else len(triangles)):
                continue
            triangulation = mtri.Triangulation(points[:, 0], points[:, 1], triangles)
            return Field("temperature", "temperature", "°C", values.astype(float), centre,
                         triangulation, "RdYlBu_r")
    return None


def principal_stresses(sxx, syy, sxy):
    """(smin, smax): the principal stresses (tension +)."""
    centre, radius = (sxx + syy) / 2, np.hypot((sxx - syy) / 2, sxy)
    return centre - radius, centre + radius


def block_field(choice, outdir, h5, t, group, blocks, free_triangles):
    """The Field to fill the blocks with (None: plain blocks); `blocks` is the
    triangulation of the free blocks, `free_triangles` selects their triangles."""
    if choice in ("auto", "temperature"):
        temperature = xdmf_temperature(outdir, h5, t)
        if temperature is not None or choice == "temperature":
            return temperature
    if blocks is None:  # every block is fixed
        return None
    if choice == "vmag":  # the blocks' speed (a shaken rock mass, docs/dda.md section 10)
        speed = np.linalg.norm(group["velocity"][...][:, :2], axis=1)
        return Field("vmag", "speed |v|", "m/s", speed, "node", blocks, "magma")
    displacement = np.linalg.norm(group["displacement"][...][:, :2], axis=1)
    if choice == "umag" or (choice == "auto" and displacement.max(initial=0.0) > 0.0):
        return Field("umag", "displacement |u|", "m", displacement, "node", blocks, "viridis")
    sxx, syy, sxy = (group[k][...][free_triangles] for k in ("sxx", "syy", "sxy"))
    smin, smax = principal_stresses(sxx, syy, sxy)
    stresses = {"smin": smin, "smax": smax, "sxx": sxx, "syy": syy, "sxy": sxy}
    if choice == "auto":
        choice = "smin" if np.abs(smin).max(initial=0.0) > 0.0 else "none"
    if choice == "none":
        return None
    label, values = STRESS_LABELS[choice], stresses[choice]
    # Compression blue, tension red, zero white when the stresses have both signs.
    both_signs = values.min(initial=0.0) < 0.0 < values.max(initial=0.0)
    cmap = "RdBu_r" if both_signs else ("Blues_r" if values.max(initial=0.0) <= 0 else "Reds")
    return Field(choice, label, "Pa", values.astype(float), "cell", blocks, cmap)


# --- the fracture field ------------------------------------------------------

def fracture_field(choice, h5, group):
    """(lines, segment values, label, unit, line widths, width note), or None:
    the fractures are drawn only where the frame has the flow's state."""
    flow = group.get("fractures")
    network = fracture_network(h5, group)
    if choice == "none" or flow is None or network is None:
        return None
    nodes, segments = network
    if len(segments) == 0:
        return None
    available = {
        "pressure": ("fluid pressure", "Pa", "pressure"),
        "head": ("hydraulic head", "m", "head"),
        "flux": ("flux |q|", "m^2/s", "flux"),
        "aperture": ("hydraulic aperture", "m", "aperture_mean"),
    }
    if choice == "auto":
        for name in ("pressure", "flux", "aperture"):
            if available[name][2] in flow and np.ptp(flow[available[name][2]][...]) > 0:
                choice = name
                break
        else:
            choice = "pressure"
    label, unit, key = available[choice]
    if key not in flow:
        return None
    values = flow[key][...].astype(float)
    if len(values) == len(nodes):  # node values: the segment's mean
        values = values[segments].mean(axis=1)
    elif len(values) != len(segments):
        return None
    if choice == "flux":
        values = np.abs(values)
    # Each segment as thick as the flow it carries (square root: the small
    # flows stay visible), as UDEC draws flow rates.
    widths, note = np.full(len(segments), 1.4), ""
    if "flux" in flow and len(flow["flux"]) == len(segments):
        q = np.abs(flow["flux"][...])
        if q.max(initial=0.0) > 0.0:
            widths = 0.5 + 3.0 * np.sqrt(q / q.max())
            note = f"line width ~ sqrt|q|, |q| <= {q.max():.2g} m²/s"
    return nodes[segments], values, label, unit, widths, note


# --- drawing -----------------------------------------------------------------

def add_blocks(ax, mesh, x, chosen, **style):
    """The chosen blocks filled plainly: one compound path per block, so that
    holes stay open."""
    if len(chosen) == 0:
        return
    paths = [MplPath.make_compound_path(*[MplPath(np.vstack([r, r[:1]]), closed=True)
                                          for r in rings])
             for rings in block_rings(mesh, x, chosen)]
    ax.add_collection(PathCollection(paths, edgecolor="0.55", linewidths=0.0, **style))


def add_colour_bar(fig, divider, mappable, label, pad):
    cax = divider.append_axes("right", size="2.5%", pad=pad)
    fig.colorbar(mappable, cax=cax, label=label)


def free_blocks(mesh, x):
    """(fixed, free_triangles, blocks): which blocks are fixed, which block
    triangles belong to free blocks, and the triangulation of those (None when
    every block is fixed). The field is drawn on the free blocks; the fixed
    ones (the boundary) are hatched."""
    fixed = mesh["block_fixed"][...].astype(bool)
    free_triangles = ~fixed[mesh["triangle_block"][...]]
    triangles = mesh["triangles"][...][free_triangles]
    blocks = mtri.Triangulation(x[:, 0], x[:, 1], triangles) if len(triangles) else None
    return fixed, free_triangles, blocks


def initial_outlines(mesh, x):
    """(x0, moved): the blocks' initial vertices, and whether the blocks moved
    visibly (a thousandth of the model): their initial outlines are then drawn
    dashed beneath."""
    x0 = mesh["initial_vertices"][...]
    model_size = float(np.ptp(x0, axis=0).max()) if len(x0) else 0.0
    return x0, len(x) > 0 and float(np.abs(x - x0).max()) > 1e-3 * model_size


def outline_width(n_blocks):
    return float(np.clip(15 / math.sqrt(max(n_blocks, 1)), 0.15, 0.8))


def add_image(ax, field, values, cmap):
    """`values` of `field` (at its nodes: gouraud shading, or its cells: one
    colour each) on `ax`; the image."""
    if field.centre == "node":
        return ax.tripcolor(field.triangulation, values, shading="gouraud", cmap=cmap)
    return ax.tripcolor(field.triangulation, facecolors=values, shading="flat", cmap=cmap,
                        edgecolors="none")


def add_block_layers(ax, mesh, x, fixed, field, width, plain="0.88"):
    """Plain free blocks when there is no field (`plain`: their colour), the
    fixed blocks hatched, and every block's outline."""
    if field is None:
        add_blocks(ax, mesh, x, np.flatnonzero(~fixed), facecolor=plain)
    # A temperature is drawn on the fixed blocks too: only their hatching then.
    on_fixed = field is not None and field.name == "temperature"
    add_blocks(ax, mesh, x, np.flatnonzero(fixed), facecolor="none" if on_fixed else "0.8",
               hatch="////")
    ax.add_collection(LineCollection(outline_segments(mesh, x), colors="black", linewidths=width))


def add_fractures(ax, fractures, field, thin=False):
    """The fractures as lines coloured by their field (`thin`: as if dense, in
    a panel that shows them small); the collection (for its colour bar) and
    its label."""
    lines, values, label, unit, widths, note = fractures
    values, unit = scaled(values, unit)
    widths = widths.copy()
    dense = len(lines) > 2000 or thin
    if dense:  # thinner lines, and no casing, which would cover the picture
        widths *= 0.5
    else:  # a dark casing under each line keeps it visible on any block colour
        ax.add_collection(LineCollection(lines, colors="0.1", linewidths=widths + 0.8,
                                         capstyle="round", zorder=3))
    # Colours that differ from the blocks' (plasma beside temperature's red-blue).
    cmap = "viridis" if field is not None and field.name == "temperature" else "plasma"
    collection = LineCollection(lines, array=values, cmap=cmap, linewidths=widths,
                                capstyle="round", zorder=3)
    ax.add_collection(collection)
    return collection, f"fracture {label} ({unit})" + (f"\n{note}" if note else "")


def add_contacts(ax, group):
    """The open and the sliding contacts; their legend handles."""
    handles = []
    if "contacts" not in group:
        return handles
    points, states = group["contacts/points"][...], group["contacts/state"][...]
    for state, name, colour, marker in CONTACT_STATES:
        chosen = states == state
        if chosen.any():
            handles.append(ax.scatter(points[chosen, 0], points[chosen, 1], s=10,
                                      color=colour, marker=marker, linewidths=0.8, zorder=4,
                                      label=f"{name} contacts ({chosen.sum()})"))
    return handles


def add_legend(ax, handles):
    if handles:  # below the x label, clear of the drawing
        ax.legend(handles=handles, fontsize="small", loc="upper center",
                  bbox_to_anchor=(0.5, 0), borderaxespad=3.8, ncol=min(len(handles), 4))



def frame_axes(ax, lo, hi, size):
    """The box [lo, hi] with 2 % of its larger side around it, in metres, equal axes."""
    pad = 0.02 * size.max()
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")

def draw(outdir, h5, frames, args, png):
    t, group = frames[-1]
    mesh = h5["mesh"]
    x = group["vertices"][...]
    fixed, free_triangles, blocks = free_blocks(mesh, x)
    field = block_field(args.field, outdir, h5, t, group, blocks, free_triangles)
    fractures = fracture_field(args.fractures, h5, group)

    x0, moved = initial_outlines(mesh, x)
    drawn = np.concatenate([x] + ([x0] if moved else []) +
                           ([fractures[0].reshape(-1, 2)] if fractures else []))
    lo, hi = drawn.min(axis=0), drawn.max(axis=0)
    size = np.maximum(hi - lo, 1e-12)
    aspect = size[1] / size[0]
    fig, ax = plt.subplots(figsize=(10, float(np.clip(8.4 * aspect, 3.0, 9.5)) + 1.2))
    divider = make_axes_locatable(ax)
    n_blocks = len(mesh["block_fixed"])
    width = outline_width(n_blocks)

    if field is not None:
        values, unit = scaled(field.values, field.unit)
        image = add_image(ax, field, values, field.cmap)
        if field.cmap == "RdBu_r":  # zero at the middle of the colour bar
            limit = float(np.abs(values).max())
            image.set_clim(-limit, limit)
        elif field.name == "umag":  # a magnitude: its scale starts at zero
            image.set_clim(0.0, max(float(values.max()), 1e-300))
        sign = ", tension +" if field.name in ("smin", "smax", "sxx", "syy") else ""
        add_colour_bar(fig, divider, image, f"{field.label} ({unit}{sign})", 0.1)
    add_block_layers(ax, mesh, x, fixed, field, width)
    handles = []  # of the one legend, below the drawing
    if moved:
        handles.append(ax.add_collection(
            LineCollection(outline_segments(mesh, x0), colors="0.45", linewidths=width,
                           linestyles=(0, (4, 3)), zorder=0.5, label="initial outlines")))

    if fractures is not None:
        collection, label = add_fractures(ax, fractures, field)
        add_colour_bar(fig, divider, collection, label, 0.8 if field is not None else 0.1)

    if args.contacts:
        handles += add_contacts(ax, group)
    handles += add_markers(ax, moved_monitors(outdir, point_markers(h5)))
    add_legend(ax, handles)

    frame_axes(ax, lo, hi, size)
    ax.set_title(title(outdir, t, len(frames)) + "\n" +
                 blocks_shown(n_blocks, int(fixed.sum()), field, fractures), fontsize="medium")
    fig.savefig(png, dpi=args.dpi, bbox_inches="tight")
    plt.close(fig)


# --- blocks in a continuum ----------------------------------------------------

# A block region narrower than this fraction of the continuum gets a second
# panel, zoomed on it with this margin (a fraction of its larger side) on
# every side.
ZOOM_BELOW = 0.1
ZOOM_MARGIN = 0.5
# The units of a picture of both: one scale for the blocks and the continuum.
BOTH_UNITS = {"m": (1e-3, "mm"), "Pa": (1e6, "MPa")}


def both_field_choice(choice, outdir, h5, t, group, c):
    """The field that colours the blocks and the continuum (--field; auto:
    the temperature where either has heat, else |u| where anything moved,
    else the most compressive principal stress where anything is stressed,
    else none)."""
    if choice != "auto":
        return choice
    if xdmf_temperature(outdir, h5, t) is not None or "temperature_change" in c:
        return "temperature"
    moved = float(np.abs(group["displacement"][...]).max(initial=0.0)) > 0.0 or \
        float(np.abs(c["displacement"][...]).max(initial=0.0)) > 0.0
    if moved:
        return "umag"
    stressed = any(float(np.abs(g[k][...]).max(initial=0.0)) > 0.0
                   for g in (group, c) for k in ("sxx", "syy", "sxy"))
    return "smin" if stressed else "none"


def continuum_field(choice, c, triangulation):
    """The Field `choice` (one of BLOCK_FIELDS but auto and none) on the
    continuum's triangles: the temperature and |u| at the vertices, the
    stresses per triangle; None when the frame lacks it."""
    if choice == "temperature":
        if "temperature" not in c:
            return None
        return Field(choice, "temperature", "°C", c["temperature"][...].astype(float), "node",
                     triangulation, "RdYlBu_r")
    if choice == "vmag":  # the continuum has no velocity field
        return None
    if choice == "umag":
        u = c["displacement"][...]
        return Field(choice, "displacement |u|", "m", np.hypot(u[:, 0], u[:, 1]), "node",
                     triangulation, "viridis")
    if any(k not in c for k in ("sxx", "syy", "sxy")):
        return None
    sxx, syy, sxy = (c[k][...].astype(float) for k in ("sxx", "syy", "sxy"))
    smin, smax = principal_stresses(sxx, syy, sxy)
    values = {"smin": smin, "smax": smax, "sxx": sxx, "syy": syy, "sxy": sxy}[choice]
    return Field(choice, STRESS_LABELS[choice], "Pa", values, "cell", triangulation, "RdBu_r")


def common_scale(name, values):
    """(cmap, limits) of the blocks' and the continuum's values together, as
    the blocks alone are drawn: |u| from zero, a temperature over its range,
    stresses red-blue about zero when they have both signs, else blues
    (compression) or reds (tension)."""
    lo, hi = (float(values.min()), float(values.max())) if len(values) else (0.0, 0.0)
    if name == "umag":
        return "viridis", (0.0, max(hi, 1e-300))
    if hi - lo <= 1e-9 * max(abs(lo), abs(hi)):  # uniform: its colour mid-scale
        spread = max(0.05 * abs(lo), 1.0)
        lo, hi = lo - spread, hi + spread
    if name == "temperature":
        return "RdYlBu_r", (lo, hi)
    if lo < 0.0 < hi:
        limit = max(-lo, hi)
        return "RdBu_r", (-limit, limit)
    return ("Blues_r" if hi <= 0 else "Reds"), (lo, hi)


def zoom_box(x, c_lo, c_hi):
    """(lo, hi) of the panel zoomed on the blocks `x`, or None when the block
    region is not much smaller than the continuum (c_lo, c_hi)."""
    lo, hi = x.min(axis=0), x.max(axis=0)
    size = float(np.max(hi - lo))
    if size <= 0.0 or size >= ZOOM_BELOW * float(np.max(c_hi - c_lo)):
        return None
    margin = ZOOM_MARGIN * size
    return lo - margin, hi + margin


def inside(markers, lo, hi):
    """`markers` without the points outside the box (lo, hi)."""
    return {kind: [(n, p) for n, p in points
                   if lo[0] <= p[0] <= hi[0] and lo[1] <= p[1] <= hi[1]]
            for kind, points in markers.items()}


def draw_with_continuum(outdir, h5, frames, args, png):
    """Blocks tied to a continuum around them (docs/output.md, "Pictures"):
    the continuum's triangles and the blocks coloured by one field on one
    scale, the blocks on top with their outlines; the whole continuum, and
    beside it the block region zoomed in when it is small."""
    t, group = frames[-1]
    mesh, c = h5["mesh"], group["continuum"]
    x = group["vertices"][...]
    fixed, free_triangles, blocks = free_blocks(mesh, x)
    cx = mesh["continuum_vertices"][...]
    continuum = mtri.Triangulation(cx[:, 0], cx[:, 1], mesh["continuum_triangles"][...])
    choice = both_field_choice(args.field, outdir, h5, t, group, c)
    fields = []  # (field, where): the blocks' and the continuum's
    if choice != "none":
        fields = [(f, where) for f, where in
                  ((continuum_field(choice, c, continuum), "continuum"),
                   (block_field(choice, outdir, h5, t, group, blocks, free_triangles), "blocks"))
                  if f is not None]
    fractures = fracture_field(args.fractures, h5, group)
    x0, moved = initial_outlines(mesh, x)

    # One unit and one colour scale for both.
    cmap, limits, factor, unit = None, None, 1.0, ""
    if fields:
        factor, unit = BOTH_UNITS.get(fields[0][0].unit, (1.0, fields[0][0].unit))
        cmap, limits = common_scale(choice, np.concatenate([f.values for f, _ in fields]) / factor)

    c_lo, c_hi = cx.min(axis=0), cx.max(axis=0)
    everything = np.vstack([cx, x] + ([fractures[0].reshape(-1, 2)] if fractures else []))
    views = [(everything.min(axis=0), everything.max(axis=0))]
    detail = np.vstack([x] + ([x0] if moved else []) +
                       ([fractures[0].reshape(-1, 2)] if fractures else []))
    zoom = zoom_box(detail, c_lo, c_hi) if len(x) else None
    if zoom is not None:
        views.append(zoom)
    sizes = [np.maximum(hi - lo, 1e-12) for lo, hi in views]
    panel_h = float(np.clip(8.4 / len(views), 5.0, 8.4))
    widths = [panel_h * s[0] / s[1] for s in sizes]
    fig, axes = plt.subplots(1, len(views), squeeze=False,
                             figsize=(sum(widths) + 1.1 * len(views) + 1.0 +
                                      (0.9 if fractures else 0.0), panel_h + 1.4),
                             gridspec_kw={"width_ratios": widths})
    axes = axes[0]
    n_blocks = len(mesh["block_fixed"])
    markers = moved_monitors(outdir, point_markers(h5))
    outline = material_outlines(h5, continuum)
    image, collection, handles, marker_handles = None, None, [], []
    for k, (ax, (lo, hi), size) in enumerate(zip(axes, views, sizes)):
        overview = k == 0 and zoom is not None
        # The continuum beneath everything of the blocks (zorder 1 and up).
        on_continuum = [f for f, where in fields if where == "continuum"]
        if on_continuum:
            image = add_image(ax, on_continuum[0], on_continuum[0].values / factor, cmap)
            image.set_clim(*limits)
        else:
            image = ax.tripcolor(continuum, facecolors=np.zeros(len(continuum.triangles)),
                                 cmap=ListedColormap(["0.93"]), edgecolors="none")
        image.set_zorder(0.6)
        # Its triangles and regions, light on the dark colours, dark on the pale.
        dark = cmap == "viridis"
        ax.triplot(continuum, color="0.85" if dark else "0.3", alpha=0.4 if dark else 0.35,
                   linewidth=0.15 if overview else 0.35, zorder=0.7)
        if outline:
            ax.add_collection(LineCollection(outline, colors="white" if dark else "0.3",
                                             linewidths=0.7, zorder=0.8))
        width = outline_width(n_blocks) * (0.5 if overview else 1.0)
        if moved and not overview:  # over the continuum, under the blocks
            handles = [ax.add_collection(
                LineCollection(outline_segments(mesh, x0), colors="0.45", linewidths=width,
                               linestyles=(0, (4, 3)), zorder=0.9, label="initial outlines"))]
        on_blocks = [f for f, where in fields if where == "blocks"]
        if on_blocks:
            image = add_image(ax, on_blocks[0], on_blocks[0].values / factor, cmap)
            image.set_clim(*limits)
        add_block_layers(ax, mesh, x, fixed, on_blocks[0] if on_blocks else None, width,
                         plain="0.8")
        if fractures is not None:
            collection, fracture_label = add_fractures(
                ax, fractures, fields[0][0] if fields else None, thin=overview)
        if overview:  # where the other panel looks
            ax.add_patch(Rectangle(zoom[0], *(zoom[1] - zoom[0]), fill=False, edgecolor="black",
                                   linewidth=0.9, linestyle=(0, (4, 2)), zorder=5))
            marker_handles = add_markers(ax, markers)  # all of them: the legend's
        else:
            if args.contacts:
                handles += add_contacts(ax, group)
            shown = add_markers(ax, inside(markers, lo, hi) if zoom is not None else markers)
            marker_handles = marker_handles or shown
        frame_axes(ax, lo, hi, size)
        if zoom is not None:
            ax.set_title("the whole model" if overview else
                         "the blocks (the dashed box of the left panel)", fontsize="medium")

    divider = make_axes_locatable(axes[-1])
    if fields:
        sign = ", tension +" if choice in ("smin", "smax", "sxx", "syy") else ""
        add_colour_bar(fig, divider, image, f"{fields[0][0].label} ({unit}{sign})", 0.1)
    if collection is not None:
        add_colour_bar(fig, divider, collection, fracture_label, 0.8 if fields else 0.1)
    add_legend(axes[-1], handles + marker_handles)
    coloured = (f"coloured by {fields[0][0].label}" + ("" if len(fields) == 2 else
                f" (on the {fields[0][1]} only)") if fields else "not coloured (no field)")
    fig.suptitle(title(outdir, t, len(frames)) + "\n" +
                 f"{n_blocks} block{'s' if n_blocks != 1 else ''}"
                 f"{f' ({int(fixed.sum())} fixed, hatched)' if fixed.any() else ''} in a "
                 f"continuum of {len(continuum.triangles)} triangles, {coloured}"
                 + (f"; fractures by {fractures[2]}" if fractures else ""), fontsize="medium")
    fig.tight_layout()
    fig.savefig(png, dpi=args.dpi, bbox_inches="tight")
    plt.close(fig)


def title(outdir, t, n_frames):
    """The first line of the title: scene, time (in the scene's unit), frame
    and how the run ended when it did not complete."""
    summary = run_summary(outdir)
    scene = summary.get("scene", outdir.name)
    status = summary.get("status")
    status = f", run {status}" if status not in (None, "completed") else ""
    return (f"{scene}: final state, {readable_time(t, summary)} "
            f"(frame {n_frames} of {n_frames}{status})")


def blocks_shown(n_blocks, n_fixed, field, fractures):
    shown = f"coloured by {field.label}" if field is not None else "not coloured (no field)"
    if fractures is not None:
        shown += f"; fractures by {fractures[2]}"
    fixed = f" ({n_fixed} fixed, hatched)" if n_fixed else ""
    return f"{n_blocks} block{'s' if n_blocks != 1 else ''}{fixed} {shown}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", type=Path, help="output folder of a run")
    parser.add_argument("--field", default="auto",
                        help=f"block field: {', '.join(BLOCK_FIELDS)} (default: auto, see above; "
                        f"smin, smax: the principal stresses), also for blocks in a continuum; "
                        f"for a continuum alone a comma list of {', '.join(CONTINUUM_FIELDS)}")
    parser.add_argument("--fractures", default="auto", choices=FRACTURE_FIELDS,
                        help="fracture field with flow (default: auto: the pressure where it "
                        "varies)")
    parser.add_argument("--contacts", action="store_true",
                        help="mark the open and the sliding contacts")
    parser.add_argument("--layout", default="auto", choices=("auto", "map", "profile"),
                        help="a continuum as maps or as profiles along its long side (default: "
                        "auto: profiles for a thin strip)")
    parser.add_argument("--dpi", type=int, default=140, help="resolution (default: 140)")
    parser.add_argument("-o", "--output", default="final_state.png",
                        help="PNG file name inside OUTDIR (default: final_state.png)")
    args = parser.parse_args()

    h5_file = args.outdir / "results.h5"
    if not h5_file.is_file():
        print(f"plot_final_state.py: {h5_file} not found (output.hdf5 off?); nothing to draw")
        return 0
    try:
        h5 = h5py.File(h5_file, "r")
    except OSError as e:  # not HDF5, or being flushed by a run at this instant
        sys.exit(f"plot_final_state.py: cannot read {h5_file}: {e}")
    with h5:
        frames = complete_frames(h5)
        if frames and is_continuum_frame(frames[-1][1]):
            png = args.outdir / args.output
            draw_continuum(title(args.outdir, frames[-1][0], len(frames)), h5, frames[-1][1], args,
                           png, axisymmetric(run_summary(args.outdir)))
            print(png)
            return 0
        if args.field not in BLOCK_FIELDS:
            parser.error(f"--field {args.field}: expected one of {', '.join(BLOCK_FIELDS)} for "
                         f"blocks (and a continuum around them)")
        if frames and len(frames[-1][1]["vertices"]) > 0 and has_continuum(h5, frames[-1][1]):
            png = args.outdir / args.output
            draw_with_continuum(args.outdir, h5, frames, args, png)
            print(png)
            return 0
        if frames and len(frames[-1][1]["vertices"]) == 0 and fracture_network(
                h5, frames[-1][1]) is None:
            frames = []  # neither blocks nor fractures
        if not frames:
            print(f"plot_final_state.py: {h5_file} has no complete frame with blocks or fractures; "
                  f"nothing to draw")
            return 0
        png = args.outdir / args.output
        draw(args.outdir, h5, frames, args, png)
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
