#!/usr/bin/env python3
"""Plot the monitors of a Fissure run (docs/output.md).

    scripts/plot_monitors.py OUTDIR [-o NAME]

Reads OUTDIR/monitors.csv and draws, for every monitor, against time the
columns the run wrote, one panel each: its displacements ux and uy, the fluid
pressure p, the temperature T, and the stresses sxx, syy, sxy of its block. Writes OUTDIR/monitors.png (or
OUTDIR/NAME) and prints the path. A run without monitors is not an error: the
script says so and exits with status 0.
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
except ImportError as e:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_monitors.py: {e.name} is missing; install python3-numpy and "
             f"python3-matplotlib (Debian) or run the script with /usr/bin/python3")

# (columns, axis label) per panel, in the order of monitors.csv (docs/output.md).
PANELS = ((("ux", "uy"), "displacement (m)"),
          (("p",), "fluid pressure (Pa)"),
          (("T",), "temperature (°C)"),
          (("sxx", "syy", "sxy"), "stress (Pa, tension +)"))


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


def plot(t, monitors, png):
    # One panel per kind of column the run wrote, in the order of monitors.csv.
    panels = [(quantities, label) for quantities, label in PANELS
              if any(q in m for m in monitors.values() for q in quantities)]
    if not panels:
        return False
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 3.2 * len(panels) + 0.6), sharex=True,
                             squeeze=False)
    for ax, (quantities, label) in zip(axes[:, 0], panels):
        for name, q in monitors.items():
            for quantity, style in zip(quantities, ("-", "--", ":")):
                if quantity in q:
                    ax.plot(t, q[quantity], style, label=f"{name} {quantity}")
        ax.set_ylabel(label)
        ax.legend(fontsize="small", ncol=len(quantities))
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("t (s)")
    fig.suptitle(f"monitors ({len(t)} output times)")
    fig.tight_layout()
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
    if not plot(t, monitors, png):
        print(f"plot_monitors.py: {csv_file} has no column to plot")
        return 0
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
