"""The final state of the poro-thermo-elastic continuum (docs/output.md,
"Pictures"; docs/continuum.md 5), for plot_final_state.py.

A model of ordinary shape is drawn as maps of the chosen fields on its
triangles, with the outlines of its materials' regions; a thin strip (one
side at least 8 times the other: a column, a ring's radial slice) as
profiles of every field along its long side. The axisymmetric continuum is
drawn in r and z, with its hoop stress. Monitors, wells and heat sources are
marked.
"""
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.ticker import NullFormatter
from mpl_toolkits.axes_grid1 import make_axes_locatable

from fissure_results import point_markers, si_prefix
from picture_markers import add_markers

# The fields a map can show (--field), by the name of its dataset in the
# frame's continuum/ group, with its label and SI unit. Stresses are tension
# positive; the axisymmetric stresses are srr, szz, srz and shoop.
FIELDS = {
    "pressure": ("pore pressure p", "Pa"),
    "excess_pressure": ("excess pore pressure p - p0", "Pa"),
    "temperature": ("temperature T", "°C"),
    "temperature_change": ("temperature change T - T0", "K"),
    "umag": ("displacement |u|", "m"),
    "ux": ("displacement ux", "m"),
    "uy": ("displacement uy", "m"),
    "sxx": ("stress σxx", "Pa"),
    "syy": ("stress σyy", "Pa"),
    "sxy": ("stress σxy", "Pa"),
    "szz": ("stress σzz", "Pa"),
    "srr": ("stress σrr", "Pa"),
    "srz": ("stress σrz", "Pa"),
    "shoop": ("hoop stress σθθ", "Pa"),
    "permeability": ("permeability k (geometric mean)", "m²"),
    "permeability_change": ("permeability change log10(k / k0)", "decades"),
}
AXISYMMETRIC_LABELS = {"ux": "displacement ur", "uy": "displacement uz", "szz": "stress σzz"}
# A side this many times the other makes a thin strip, drawn as profiles.
STRIP_ASPECT = 8


def node_values(c, name, triangulation):
    """The field `name` at the vertices: the frame's node data, or cell data
    averaged onto the vertices (area-weighted), or None when absent."""
    if name in ("umag", "ux", "uy"):
        u = c["displacement"][...]
        return {"umag": np.hypot(u[:, 0], u[:, 1]), "ux": u[:, 0], "uy": u[:, 1]}[name]
    if name not in c:
        return None
    values = c[name][...].astype(float)
    n = len(triangulation.x)
    if len(values) == n:
        return values
    triangles = triangulation.triangles
    x, y = triangulation.x[triangles], triangulation.y[triangles]
    area = 0.5 * np.abs((x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) -
                        (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0]))
    total, weight = np.zeros(n), np.zeros(n)
    for k in range(3):
        np.add.at(total, triangles[:, k], area * values)
        np.add.at(weight, triangles[:, k], area)
    return total / np.maximum(weight, 1e-300)


def label(name, axisymmetric):
    text, unit = FIELDS[name]
    if axisymmetric:
        text = AXISYMMETRIC_LABELS.get(name, text)
    return text, unit


def auto_fields(c):
    """The maps drawn by default: with heat the temperature change and the
    excess pore pressure, without it the excess pore pressure and the
    displacement (the pore pressure itself where it starts at zero, and in
    results from before the excess fields)."""
    pressure = "pressure"
    if "excess_pressure" in c and not np.array_equal(c["excess_pressure"][...],
                                                     c["pressure"][...]):
        pressure = "excess_pressure"
    if "temperature_change" in c:
        # A permeability that follows the stress: how far it moved, too.
        if "permeability_change" in c:
            return ["temperature_change", pressure, "permeability_change"]
        return ["temperature_change", pressure]
    if "excess_pressure" not in c and "temperature" in c and np.ptp(c["temperature"][...]) > 0:
        return ["temperature", pressure]
    return [pressure, "umag"]


def colour_scale(name, values):
    """(cmap, limits) of a field. Absolute fields (pressure, temperature,
    |u|) on sequential maps; changes and stresses white at zero: red-blue
    centred on zero where both signs matter, else reds for a rise
    (tension), blues for a fall (compression), from zero. A part of the
    other sign below 5 % of the largest magnitude (an undershoot) is not
    given a colour of its own."""
    lo, hi = float(np.nanmin(values)), float(np.nanmax(values))
    if name in ("pressure", "temperature", "umag"):
        return {"pressure": "viridis", "temperature": "inferno", "umag": "viridis"}[name], \
            ((0.0, max(hi, 1e-300)) if name == "umag" else (lo, hi))
    big = max(abs(lo), abs(hi), 1e-300)
    if lo < -0.05 * big and hi > 0.05 * big:
        return "RdBu_r", (-big, big)
    if hi > 0.05 * big:
        return "Reds", (0.0, hi)
    return "Blues_r", (lo, 0.0)


def material_outlines(h5, triangulation):
    """The edges between triangles of different materials."""
    material = h5["mesh/continuum_material"][...]
    owner, outline = {}, []
    points = np.column_stack([triangulation.x, triangulation.y])
    for cell, tri in enumerate(triangulation.triangles):
        for k in range(3):
            edge = tuple(sorted((tri[k], tri[(k + 1) % 3])))
            if edge in owner and material[owner[edge]] != material[cell]:
                outline.append(points[list(edge)])
            owner[edge] = cell
    return outline


def draw_maps(fig_title, h5, c, triangulation, names, axisymmetric, markers, args, png):
    x, y = triangulation.x, triangulation.y
    size = np.maximum(np.array([np.ptp(x), np.ptp(y)]), 1e-12)
    n = len(names)
    # Wide models one above the other, the others side by side; a panel
    # of about 10 inches across the page, or 6 inches high.
    stacked = size[0] >= 1.6 * size[1]
    aspect = size[1] / size[0]
    if stacked:
        panel_w = 10.0 if n == 1 else 9.0
        panel_h = panel_w * aspect
    else:
        panel_h = float(np.clip(10.0 / n * aspect, 3.0, 6.0))
        panel_w = panel_h / aspect
    title_h = 0.25 + 0.2 * (fig_title.count("\n") + 1)
    fig, axes = plt.subplots(n if stacked else 1, 1 if stacked else n, squeeze=False,
                             figsize=(panel_w + 1.6 if stacked else n * (panel_w + 1.8),
                                      (n * (panel_h + 0.9) if stacked else panel_h + 0.9)
                                      + 0.6 + title_h))
    outline = material_outlines(h5, triangulation)
    axis_names = ("r", "z") if axisymmetric else ("x", "y")
    handles = []
    for ax, name in zip(axes.flat, names):
        values = node_values(c, name, triangulation)
        text, unit = label(name, axisymmetric)
        factor, unit = si_prefix(values, unit)
        values = values / factor
        cmap, limits = colour_scale(name, values)
        image = ax.tripcolor(triangulation, values, shading="gouraud", cmap=cmap)
        image.set_clim(*limits)
        cax = make_axes_locatable(ax).append_axes("right", size="2.5%", pad=0.1)
        sign = ", tension +" if FIELDS[name][1] == "Pa" and name.startswith("s") else ""
        fig.colorbar(image, cax=cax, label=f"{text} ({unit}{sign})")
        ax.triplot(triangulation, color="0.3", linewidth=0.15, alpha=0.4)
        if outline:  # white on the dark maps, dark on those white at zero
            dark = cmap in ("viridis", "inferno")
            ax.add_collection(LineCollection(outline, colors="white" if dark else "0.3",
                                             linewidths=1.0 if dark else 0.7))
        handles = add_markers(ax, markers)
        pad = 0.02 * size.max()
        ax.set_xlim(x.min() - pad, x.max() + pad)
        ax.set_ylim(y.min() - pad, y.max() + pad)
        ax.set_aspect("equal")
        ax.set_xlabel(f"{axis_names[0]} (m)")
        ax.set_ylabel(f"{axis_names[1]} (m)")
        ax.set_title(text, fontsize="medium")
    if handles:
        fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize="small",
                   frameon=False)
    fig.suptitle(fig_title, fontsize="medium")
    height = fig.get_figheight()
    fig.tight_layout(rect=(0, 0.45 / height if handles else 0, 1, 1 - title_h / height))
    fig.savefig(png, dpi=args.dpi, bbox_inches="tight")
    plt.close(fig)


def draw_profile(fig_title, c, triangulation, axisymmetric, markers, args, png):
    """Every field against the strip's long side, sampled along its middle."""
    x, y = triangulation.x, triangulation.y
    size = np.array([np.ptp(x), np.ptp(y)])
    along = int(np.argmax(size))  # 0: the strip lies along x (r), 1: along y (z)
    coordinate = (x, y)[along]
    middle = 0.5 * ((y, x)[along].min() + (y, x)[along].max())
    # A ring's radial slice on a logarithmic r, which spreads the near field
    # where the gradients are.
    log_r = axisymmetric and along == 0 and coordinate.min() > 0 and \
        coordinate.max() >= 10 * coordinate.min()
    s = (np.geomspace if log_r else np.linspace)(coordinate.min(), coordinate.max(), 400)
    sample = (s, np.full_like(s, middle)) if along == 0 else (np.full_like(s, middle), s)

    def at_middle(name):
        values = node_values(c, name, triangulation)
        if values is None:
            return None
        return np.ma.filled(mtri.LinearTriInterpolator(triangulation, values)(*sample), np.nan)

    stresses = ("srr", "szz", "shoop", "srz") if axisymmetric else ("sxx", "syy", "szz", "sxy")
    u_names = ("ux", "uy")
    panels = []  # (axis label, SI unit, [(curve label, values, style)])
    p, excess = at_middle("pressure"), at_middle("excess_pressure")
    curves = [("p", p, "-")]
    if excess is not None and np.nanmax(np.abs(p - excess)) > 0:
        curves.append(("p - p0 (excess)", excess, "--"))
    panels.append(("pore pressure", "Pa", curves))
    if "temperature_change" in c:
        temperature, change = at_middle("temperature"), at_middle("temperature_change")
        panels.append(("temperature", "°C", [("T", temperature, "-"),
                                              ("T0 (initial)", temperature - change, ":")]))
    panels.append(("displacement", "m",
                   [(label(n, axisymmetric)[0].split()[-1], at_middle(n), style)
                    for n, style in zip(u_names, ("-", "--"))]))
    panels.append(("stress, tension +", "Pa",
                   [(label(n, axisymmetric)[0].replace("stress ", ""), at_middle(n), style)
                    for n, style in zip(stresses, ("-", "--", "-.", ":")) if n in c]))
    if "permeability" in c:  # a permeability that follows the stress, on a log scale
        k, decades = at_middle("permeability"), at_middle("permeability_change")
        panels.append(("permeability", "m²", [("k", k, "-"), ("k0 (initial)", k / 10 ** decades, ":")]))

    axis_names = ("r", "z") if axisymmetric else ("x", "y")
    n = len(panels)
    if along == 0:  # the long side across the page: panels one above the other
        fig, axes = plt.subplots(n, 1, sharex=True, figsize=(9, 2.4 * n + 1.4), squeeze=False)
    else:  # a column: depth down the page, panels side by side
        fig, axes = plt.subplots(1, n, sharey=True, figsize=(3.1 * n + 1.0, 7.5), squeeze=False)
    for ax, (what, unit, curves) in zip(axes.flat, panels):
        factor, shown = si_prefix(np.concatenate([v for _, v, _ in curves]), unit)
        for name, values, style in curves:
            xy = (s, values / factor) if along == 0 else (values / factor, s)
            ax.plot(*xy, style, label=name, linewidth=1.5)
        if what == "permeability":
            (ax.set_yscale if along == 0 else ax.set_xscale)("log")
        value_label = f"{what} ({shown})" if "tension" not in what else f"stress ({shown}, tension +)"
        (ax.set_ylabel if along == 0 else ax.set_xlabel)(value_label)
        ax.grid(alpha=0.3)
        if len(curves) > 1:
            ax.legend(fontsize="small")
        # The monitors and sources along the strip.
        for kind, colour in (("monitor", "0.4"), ("well", "deepskyblue"),
                             ("heat_source", "orangered")):
            for name, point in markers.get(kind, []):
                (ax.axvline if along == 0 else ax.axhline)(point[along], color=colour,
                                                           linewidth=0.8, linestyle=(0, (2, 3)))
    first = axes.flat[0]
    for kind in ("monitor", "well", "heat_source"):
        for name, point in markers.get(kind, []):
            if along == 0:  # above the top panel
                first.annotate(name, (point[0], 1.0), xycoords=("data", "axes fraction"),
                               xytext=(2, 2), textcoords="offset points", fontsize="x-small",
                               rotation=90, va="bottom")
            else:  # inside the first panel, at its right edge
                first.annotate(name, (1.0, point[1]), xycoords=("axes fraction", "data"),
                               xytext=(-3, 2), textcoords="offset points", fontsize="x-small",
                               ha="right", va="bottom", color="0.3")
    if along == 0:
        if log_r:  # ticks at 1, 2, 5 x 10^k, written plainly
            first.set_xscale("log")
            ticks = [m * 10.0 ** k for k in range(-3, 6) for m in (1, 2, 5)
                     if s[0] <= m * 10.0 ** k <= s[-1]]
            first.set_xticks(ticks, [f"{v:g}" for v in ticks])
            first.xaxis.set_minor_formatter(NullFormatter())
        axes.flat[-1].set_xlabel(f"{axis_names[0]} (m{', logarithmic' if log_r else ''})")
    else:
        first.set_ylabel(f"{axis_names[1]} (m)")
    fig.suptitle(f"{fig_title}\nprofiles along {axis_names[along]} at {axis_names[1 - along]} = "
                 f"{middle:.4g} m (the model is a thin strip, {size[0]:.4g} m x {size[1]:.4g} m)",
                 fontsize="medium")
    fig.tight_layout()
    fig.savefig(png, dpi=args.dpi, bbox_inches="tight")
    plt.close(fig)


def draw_continuum(title_lines, h5, group, args, png, axisymmetric):
    """The continuum of the frame `group`: maps, or profiles of a thin strip
    (args.layout: auto, map or profile; args.field: auto or a comma list of
    FIELDS for the maps). `title_lines` start the title."""
    c = group["continuum"]
    x = h5["mesh/continuum_vertices"][...]
    triangulation = mtri.Triangulation(x[:, 0], x[:, 1], h5["mesh/continuum_triangles"][...])
    axisymmetric = axisymmetric or "shoop" in c
    markers = point_markers(h5)
    size = np.maximum(np.ptp(x, axis=0), 1e-12)
    strip = size.max() >= STRIP_ASPECT * size.min()
    geometry = "axisymmetric" if axisymmetric else "plane strain"
    title = (f"{title_lines}\ncontinuum ({geometry}), {len(triangulation.triangles)} triangles")
    if args.layout == "profile" or (args.layout == "auto" and strip):
        draw_profile(title, c, triangulation, axisymmetric, markers, args, png)
        return
    names = auto_fields(c) if args.field == "auto" else args.field.split(",")
    missing = [n for n in names if n not in FIELDS or
               (n not in ("umag", "ux", "uy") and n not in c)]
    if missing:
        available = [n for n in FIELDS if n in ("umag", "ux", "uy") or n in c]
        raise SystemExit(f"plot_final_state.py: the continuum has no field "
                         f"{', '.join(missing)}; it has {', '.join(available)}")
    draw_maps(title, h5, c, triangulation, names, axisymmetric, markers, args, png)


def is_continuum_frame(group):
    """A frame of a continuum run (no blocks)."""
    return len(group["vertices"]) == 0 and "continuum" in group


def has_continuum(h5, group):
    """A frame with a continuum (with or without blocks) and its mesh."""
    return ("continuum" in group and "continuum_vertices" in h5["mesh"]
            and "continuum_triangles" in h5["mesh"])
