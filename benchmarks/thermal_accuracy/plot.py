#!/usr/bin/env python3
"""Figures of benchmarks/thermal_accuracy (docs/thermal.md 6, docs/performance.md)."""
import csv
import pathlib
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent


def rows(name):
    with open(HERE / name, newline="") as f:
        return [{k: (float(v) if k not in ("scheme", "capacity") else v) for k, v in r.items()}
                for r in csv.DictReader(f)]


fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
by_t = defaultdict(list)
for r in rows("profiles.csv"):
    by_t[r["t"]].append(r)
for t, rs in sorted(by_t.items()):
    x = [r["x"] for r in rs]
    a.plot(x, [r["erfc"] for r in rs], "k-", lw=0.8)
    a.plot(x[::8], [r["T"] for r in rs][::8], "o", ms=3.5, label=f"t = {t:.0e} s")
a.set_xlabel("x (m)")
a.set_ylabel("T (boundary 1, initial 0)")
a.set_title("(h) 1D conduction: P1, BE, h = 0.01 m, dt = 100 s\n(lines: erfc)")
a.legend()
ls = rows("line_source.csv")
b.semilogx([r["r"] for r in ls], [r["E1"] for r in ls], "k-", lw=0.8, label="Q/(4 pi lambda) E1")
b.semilogx([r["r"] for r in ls], [r["T"] for r in ls], "o", ms=3.5, label="P1, BDF2, 100 steps")
b.set_xlabel("r (m)")
b.set_ylabel("temperature rise (K)")
b.set_title("(l) line source 1 kW/m after 1 year")
b.legend()
fig.tight_layout()
fig.savefig(HERE / "verification.png", dpi=110)

fig, ax = plt.subplots(figsize=(6, 4.5))
groups = defaultdict(list)
for r in rows("work_precision.csv"):
    groups[(r["scheme"], r["h"])].append(r)
for (scheme, h), rs in sorted(groups.items()):
    ax.loglog([r["seconds"] for r in rs], [r["error"] for r in rs], "o-" if scheme == "bdf2" else "s--",
              color="C0" if h > 0.02 else "C3", ms=4, label=f"{scheme}, h = {h:g} m")
ax.set_xlabel("wall time (s)")
ax.set_ylabel("largest nodal error")
ax.set_title("work-precision: smooth mode, 5 to 640 steps\n(wall time with meshing)")
ax.legend()
fig.tight_layout()
fig.savefig(HERE / "work_precision.png", dpi=110)

fig, ax = plt.subplots(figsize=(6.5, 4.5))
groups = defaultdict(list)
for r in rows("stability.csv"):
    groups[(r["capacity"], r["scheme"])].append(r)
for k, ((capacity, scheme), rs) in enumerate(sorted(groups.items())):
    dt = [r["dt"] for r in rs]
    worst = [max(-r["lowest"], r["highest"] - 1, 1e-12) for r in rs]
    ax.loglog(dt, worst, "o-" if capacity == "lumped" else "s--", color=f"C{k}", ms=9 - 2 * k,
              label=f"{capacity}, {scheme}")
ax.axhline(1e-2, color="grey", lw=0.6, ls=":")
ax.set_xlabel("time step (s)")
ax.set_ylabel("largest excursion beyond [0, 1]")
ax.set_title("maximum principle: cold rock heated to 1 from one side\n"
             "h = 0.05 m (h^2 / kappa = 2,070 s), 5 steps; 1e-12: none (round-off)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(HERE / "stability.png", dpi=110)

fig, ax = plt.subplots(figsize=(6, 4.5))
groups = defaultdict(list)
for r in rows("lauwerier_work_precision.csv"):
    groups[r["scheme"]].append(r)
for k, (scheme, rs) in enumerate(sorted(groups.items())):
    ax.loglog([r["seconds"] for r in rs], [r["error"] for r in rs], "o-" if scheme == "bdf2" else "s--",
              color=f"C{k}", ms=5, label=scheme)
    for r in rs:
        if scheme == "backward_euler":
            ax.annotate(f"h = {r['h']:g} m", (r["seconds"], r["error"]), textcoords="offset points",
                        xytext=(6, 4), fontsize=8)
ax.axhline(0.02, color="grey", lw=0.6, ls=":")
ax.set_xlabel("wall time (s, meshing included)")
ax.set_ylabel("largest error of theta_f at x = 2, 5, 10, 15 m")
ax.set_title("work-precision: Lauwerier (i), t = 1e6 s, dt = 4e4 h\n(dotted: the test's 0.02)")
ax.legend()
fig.tight_layout()
fig.savefig(HERE / "lauwerier_work_precision.png", dpi=110)
