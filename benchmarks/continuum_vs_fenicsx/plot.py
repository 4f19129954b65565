#!/usr/bin/env python3
"""Draws fenicsx.png from results.csv (run.py): per-step time, first step,
start-up and peak memory against the unknowns, Fissure and dolfinx."""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = pathlib.Path(__file__).resolve().parent
rows = list(csv.DictReader(open(here / "results.csv")))
series = {}
for r in rows:
    series.setdefault((r["code"], r["solver"]), []).append(r)
style = {("fissure", "umfpack"): ("C0", "o", "Fissure (UMFPACK, METIS)"),
         ("dolfinx", "umfpack"): ("C1", "s", "dolfinx 0.5.2 (UMFPACK)"),
         ("dolfinx", "mumps"): ("C2", "^", "dolfinx 0.5.2 (MUMPS)")}
panels = [("step_s", "time per step (s)"), ("first_step_s", "first step (s)"),
          ("startup_s", "start-up, undrained start included (s)"), ("peak_mb", "peak memory (MB)")]
fig, axes = plt.subplots(2, 2, figsize=(11, 8))
for ax, (key, label) in zip(axes.ravel(), panels):
    for name, rs in series.items():
        colour, marker, text = style.get(name, ("k", "x", " ".join(name)))
        ax.loglog([float(r["unknowns"]) for r in rs], [float(r[key]) for r in rs],
                  marker=marker, color=colour, label=text)
    ax.set_xlabel("unknowns of the u-p system")
    ax.set_ylabel(label)
    ax.grid(True, which="both", alpha=0.3)
axes[0, 0].legend()
fig.suptitle("Mandel's problem, Taylor-Hood P2/P1 monolithic, one core: Fissure and FEniCSx")
fig.tight_layout()
fig.savefig(here / "fenicsx.png", dpi=110)
print(f"wrote {here / 'fenicsx.png'}")
