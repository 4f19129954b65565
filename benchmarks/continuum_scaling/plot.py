#!/usr/bin/env python3
"""scaling.png from results.csv (run.py): the continuum's wall time per step
and its Krylov iterations per step against the unknowns, per solver and
number of ranks."""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent
rows = list(csv.DictReader(open(here / "results.csv")))
if not rows:
    raise SystemExit("results.csv is empty: run run.py first")


def label(r):
    # "direct" on one rank, "direct on rank 0" on several (UMFPACK/CHOLMOD
    # either way); MUMPS is PETSc's preonly.
    umfpack = r["solver"].startswith("direct")
    name = "UMFPACK/CHOLMOD" if umfpack else ("MUMPS" if "preonly" in r["solver"] else "Krylov (GMRES + AMG)")
    return f"{name}, {r['ranks']} rank{'s' if r['ranks'] != '1' else ''}"


series = {}
for r in rows:
    series.setdefault(label(r), []).append(r)

fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
for name, rs in series.items():
    n = [float(r["unknowns"]) for r in rs]
    ax.loglog(n, [float(r["per_step_s"]) for r in rs], "o-", label=name)
    if "Krylov" in name:
        bx.semilogx(n, [float(r["iterations_per_step"]) for r in rs], "o-", label=name)
ax.axhline(10, color="grey", ls=":", lw=1)
ax.annotate("target: 10 s per step at 1e6 unknowns, 2 ranks", (1.2e4, 11), fontsize=8, color="grey")
ax.set_xlabel("unknowns u-p-T")
ax.set_ylabel("wall time per step (s), set-up excluded")
ax.set_title("Mandel's slab with heat, monolithic u-p")
ax.legend(fontsize=8)
ax.grid(True, which="both", alpha=0.3)
bx.set_xlabel("unknowns u-p-T")
bx.set_ylabel("Krylov iterations per step (heat CG + u-p GMRES)")
bx.set_title("iterations against the mesh size")
bx.set_ylim(bottom=0)
bx.legend(fontsize=8)
bx.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(here / "scaling.png", dpi=120)
print(f"wrote {here / 'scaling.png'}")
