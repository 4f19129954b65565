"""The monitors, wells and heat sources on a picture of a Fissure run
(docs/output.md, "Pictures"); shared by plot_final_state.py and its
continuum pictures.

Where they are: results.h5:/mesh/markers (fissure_results.point_markers),
and for a monitor that moves with its block, its last position in
monitors.csv (columns m.x, m.y).
"""
import csv

import numpy as np
from matplotlib.lines import Line2D

# Drawn above everything else, each kind with its own symbol.
STYLES = {
    "monitor": dict(marker="o", markersize=6, markerfacecolor="white", markeredgecolor="black",
                    label="monitor"),
    "well": dict(marker="v", markersize=8, markerfacecolor="deepskyblue",
                 markeredgecolor="black", label="well"),
    "heat_source": dict(marker="*", markersize=11, markerfacecolor="orangered",
                        markeredgecolor="black", label="heat source"),
}
# More points of a kind than this are marked without their names.
MOST_NAMES = 6


def moved_monitors(outdir, markers):
    """`markers` with each monitor at its last position in monitors.csv
    (its m.x, m.y columns: a monitor moving with its block)."""
    monitors = markers.get("monitor")
    if not monitors:
        return markers
    try:
        with open(outdir / "monitors.csv", newline="") as f:
            rows = [r for r in csv.reader(f) if r]
    except OSError:
        return markers
    if len(rows) < 2:
        return markers
    header, last = rows[0], rows[-1]
    if len(last) != len(header):  # cut short by a killed run: the row before
        last = rows[-2] if len(rows) > 2 else None
    if last is None:
        return markers
    column = {name: k for k, name in enumerate(header)}
    moved = []
    for name, point in monitors:
        kx, ky = column.get(f"{name}.x"), column.get(f"{name}.y")
        try:
            moved.append((name, (float(last[kx]), float(last[ky]))) if kx and ky else
                         (name, point))
        except ValueError:  # an empty cell: no value
            moved.append((name, point))
    return {**markers, "monitor": moved}


def add_markers(ax, markers, transform=None):
    """Marks the points of `markers` ({kind: [(name, (x, y))]}) on `ax`,
    named when there are few of a kind; `transform` maps (x, y) to the axes'
    coordinates (None: as they are). Returns the legend handles."""
    handles = []
    for kind, style in STYLES.items():
        points = markers.get(kind, [])
        if not points:
            continue
        xy = np.array([p for _, p in points], dtype=float)
        if transform is not None:
            xy = transform(xy)
        few = len(points) <= MOST_NAMES
        # Many points of a kind smaller; the monitors above the sources.
        ax.plot(xy[:, 0], xy[:, 1], linestyle="none", zorder=7 if kind == "monitor" else 6,
                clip_on=False, **{k: (v if few or k != "markersize" else 0.7 * v)
                                  for k, v in style.items() if k != "label"})
        if few:
            # Monitors named above right, wells below left, sources below right:
            # a monitor beside a well stays readable.
            offset, ha, va = {"monitor": ((5, 4), "left", "bottom"),
                              "well": ((-6, -6), "right", "top"),
                              "heat_source": ((6, -6), "left", "top")}[kind]
            for (name, _), (x, y) in zip(points, xy):
                ax.annotate(name, (x, y), xytext=offset, textcoords="offset points", ha=ha,
                            va=va, fontsize="x-small", zorder=6,
                            bbox=dict(boxstyle="round,pad=0.15", facecolor="white",
                                      edgecolor="none", alpha=0.75))
        handles.append(Line2D([], [], linestyle="none",
                              **{**style, "label": f"{style['label']}s ({len(points)})"
                                 if len(points) > 1 else style["label"]}))
    return handles
