#!/usr/bin/env python3
"""Plot the monitors of a Fissure run (docs/output.md).

    scripts/plot_monitors.py OUTDIR [-o NAME]

Reads OUTDIR/monitors.csv and draws, for every monitor, against time the
columns the run wrote, one panel each: its displacements, the fluid pressure
p, the temperature T, and the stresses of its block or of the continuum at
the point. Time is in the scene's unit (summary.json `time_unit`: the unit
time.end was written in), pressures and stresses in kPa or MPa and
displacements in µm, mm or m by their size, temperatures in °C. Each monitor
keeps one colour in every panel; the line style tells the components apart.
A column without any value (a pressure monitor off the fracture network) is
left out and named below the panels. For an axisymmetric continuum the
components are named r, z and θ (x is the radius, y the axis, the
out-of-plane stress the hoop stress). Writes OUTDIR/monitors.png (or
OUTDIR/NAME) and prints the path. A run without monitors is not an error:
the script says so and exits with status 0.
"""
import argparse
import csv
import sys
from pathlib import Path

try:
    import matplotlib

    matplotlib.use("Agg")  # files only, no display needed
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.lines import Line2D
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_monitors.py: {e.name} is missing; install python3-numpy and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fissure_results import axisymmetric, run_summary, si_prefix, time_unit  # noqa: E402

# (columns, what, SI unit) per panel, in the order of monitors.csv
# (docs/output.md); the stresses are tension positive.
PANELS = ((("ux", "uy"), "displacement", "m"),
          (("p",), "fluid pressure", "Pa"),
          (("T",), "temperature", "°C"),
          (("sxx", "syy", "sxy", "szz"), "stress", "Pa"))
STYLES = ("-", "--", ":", "-.")
# How the columns read in an axisymmetric continuum (x = r, y = z, and the
# out-of-plane stress is the hoop stress).
AXISYMMETRIC = {"ux": "ur", "uy": "uz", "sxx": "σrr", "syy": "σzz", "sxy": "σrz",
                "szz": "σθθ (hoop)"}
PLANE = {"sxx": "σxx", "syy": "σyy", "sxy": "σxy", "szz": "σzz"}


def read_monitors(csv_file):
    """Returns (t, {monitor: {quantity: column}}) in file order."""
    with open(csv_file, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or not rows[0] or rows[0][0] != "t":
        sys.exit(f"plot_monitors.py: {csv_file} does not start with a 't' column")
    header, body = rows[0], []
    for number, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        try:
            if len(row) != len(header):
                raise ValueError(f"{len(row)} columns, expected {len(header)}")
            body.append([float(v) if v != "" else float("nan") for v in row])  # empty: missing
        except ValueError as e:
            # A run killed while writing may leave its last row incomplete.
            print(f"plot_monitors.py: skipping line {number} of {csv_file}: {e}", file=sys.stderr)
    data = np.array(body, dtype=float).reshape(len(body), len(header))
    monitors = {}
    for j, name in enumerate(header[1:], start=1):
        # Monitor names may contain dots; the quantity is after the last one.
        monitor, _, quantity = name.rpartition(".")
        if monitor:
            monitors.setdefault(monitor, {})[quantity] = data[:, j]
    return data[:, 0], monitors


def plot(t, monitors, png, summary):
    names = AXISYMMETRIC if axisymmetric(summary) else PLANE
    unit_name, unit_seconds = time_unit(summary)
    # Columns without a single value (NaN throughout) are left out, and named.
    empty = [f"{m}.{q}" for m, columns in monitors.items() for q, v in columns.items()
             if not np.isfinite(v).any()]
    panels = []
    for quantities, what, unit in PANELS:
        lines = [(m, q, columns[q]) for m, columns in monitors.items() for q in quantities
                 if q in columns and np.isfinite(columns[q]).any()]
        if lines:
            panels.append((quantities, what, unit, lines))
    if not panels:
        return False
    colours = {m: f"C{k % 10}" for k, m in enumerate(monitors)}
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 2.9 * len(panels) + 1.2), sharex=True,
                             squeeze=False)
    for ax, (quantities, what, unit, lines) in zip(axes[:, 0], panels):
        # One unit for the panel, from its largest value.
        factor, shown = si_prefix(np.concatenate([v for _, _, v in lines]), unit)
        for monitor, quantity, values in lines:
            ax.plot(t / unit_seconds, values / factor, STYLES[quantities.index(quantity)],
                    color=colours[monitor], linewidth=1.4)
        ax.set_ylabel(f"{what} ({shown}{', tension +' if what == 'stress' else ''})")
        ax.grid(alpha=0.3)
        present = [q for q in quantities if any(q == line[1] for line in lines)]
        if len(present) > 1:  # the line styles of the components
            ax.legend([Line2D([], [], color="0.2", linestyle=STYLES[quantities.index(q)])
                       for q in present], [names.get(q, q) for q in present],
                      fontsize="small", ncol=len(present), loc="best")
    axes[-1, 0].set_xlabel(f"t ({unit_name})")
    # The monitors' colours, once for all panels.
    fig.legend([Line2D([], [], color=colours[m], linewidth=2) for m in monitors], list(monitors),
               loc="upper center", ncol=min(len(monitors), 5), fontsize="small",
               bbox_to_anchor=(0.5, 1 - 0.5 / fig.get_figheight()), frameon=False)
    scene = summary.get("scene", png.parent.name)
    fig.suptitle(f"{scene}: monitors ({len(t)} output times)")
    bottom = 0.0
    if empty:
        fig.text(0.01, 0.005, "no values (not plotted): " + ", ".join(empty), fontsize="small",
                 color="0.35", va="bottom", wrap=True)
        bottom = 0.35 / fig.get_figheight()
    fig.tight_layout(rect=(0, bottom, 1, 1 - 0.75 / fig.get_figheight()))
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", type=Path, help="output folder of a run")
    parser.add_argument("-o", "--output", default="monitors.png",
                        help="PNG file name inside OUTDIR (default: monitors.png)")
    args = parser.parse_args()

    csv_file = args.outdir / "monitors.csv"
    if not csv_file.is_file():
        sys.exit(f"plot_monitors.py: {csv_file} not found")
    t, monitors = read_monitors(csv_file)
    if not monitors:
        print(f"plot_monitors.py: {csv_file} has no monitor columns; nothing to plot")
        return 0
    if len(t) == 0:
        print(f"plot_monitors.py: {csv_file} has no rows yet; nothing to plot")
        return 0
    png = args.outdir / args.output
    if not plot(t, monitors, png, run_summary(args.outdir)):
        print(f"plot_monitors.py: {csv_file} has no column to plot")
        return 0
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
