#!/usr/bin/python3
"""rev_stress.png: seconds per square against its blocks (benchmarks/rev_stress)."""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = pathlib.Path(__file__).resolve().parent
rows = list(csv.DictReader(open(here / "results.csv")))
fig, ax = plt.subplots(figsize=(6.5, 4.5))
for at_rest, colour, label in (("1", "tab:blue", "at rest"), ("0", "tab:red", "not at rest")):
    pts = [r for r in rows if r["at_rest"] == at_rest]
    if pts:
        ax.scatter([int(r["blocks"]) for r in pts], [float(r["seconds"]) for r in pts], s=10,
                   color=colour, alpha=0.6, label=label)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("blocks in the square")
ax.set_ylabel("seconds per square (cut, DEM to rest, flow)")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
ax.set_title("REV under stress: cost of a square")
fig.tight_layout()
fig.savefig(here / "rev_stress.png", dpi=120)
