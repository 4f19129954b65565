#!/usr/bin/env python3
"""Draws fenicsx.png from results.csv (run.py): per-step time, first step,
start-up and peak memory against the unknowns, Fissure and dolfinx; and
fenicsx_heat.png from results_heat.csv (run.py --case heat): the heat
case's per-step time and its ratio, first step, start-up, peak memory and
the error against the closed form, against the mesh nodes.

Usage: plot.py [mandel|heat|both] (default both; a case without its CSV is
skipped)."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = pathlib.Path(__file__).resolve().parent


def plot_mandel():
    rows = list(csv.DictReader(open(here / "results.csv")))
    series = {}
    for r in rows:
        series.setdefault((r["code"], r["solver"]), []).append(r)
    style = {("fissure", "umfpack"): ("C0", "o", "Fissure (UMFPACK, METIS)"),
             ("dolfinx", "umfpack"): ("C1", "s", "dolfinx 0.5.2 (UMFPACK)"),
             ("dolfinx", "mumps"): ("C2", "^", "dolfinx 0.5.2 (MUMPS)")}
    panels = [("step_s", "time per step (s)"), ("first_step_s", "first step (s)"),
              ("startup_s", "start-up, undrained start included (s)"),
              ("peak_mb", "peak memory (MB)")]
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


def plot_heat():
    rows = list(csv.DictReader(open(here / "results_heat.csv")))
    series = {}
    for r in rows:
        series.setdefault((r["code"], r["mesh"], r["rhs"], r["solver"]), []).append(r)

    def style(name):
        code, mesh, rhs, solver = name
        if code == "fissure":
            return "C0", "o", "-", "Fissure (CHOLMOD, factor reused)"
        colour = {"form": "C1", "matvec": "C2"}[rhs]
        marker = {"cholmod": "s", "mumps": "^", "petsc": "v"}.get(solver, "x")
        where = "its own mesh" if mesh == "rectangle" else "Fissure's mesh"
        line = ":" if mesh == "rectangle" else "-"
        text = f"dolfinx 0.5.2, {rhs} rhs ({solver.upper()}, {where})"
        return ("C3" if mesh == "rectangle" else colour), marker, line, text

    fissure = {r["target"]: float(r["step_s"]) for r in rows if r["code"] == "fissure"}
    fig, axes = plt.subplots(2, 3, figsize=(16, 9))
    panels = [("step_s", "time per step (s)"), ("first_step_s", "first step, the "
              "factorization included (s)"), ("startup_s", "start-up: mesh and matrices (s)"),
              ("peak_mb", "peak memory (MB)"), ("error_K", "centre temperature - closed "
              "form (K)")]
    ax_step, ax_ratio, ax_first = axes[0]
    ax_start, ax_memory, ax_error = axes[1]
    for ax, (key, label) in zip([ax_step, ax_first, ax_start, ax_memory, ax_error], panels):
        for name, rs in series.items():
            colour, marker, line, text = style(name)
            x = [float(r["nodes"]) for r in rs]
            y = [float(r[key]) for r in rs]
            if key == "error_K":
                ax.semilogx(x, y, marker=marker, color=colour, linestyle=line, label=text)
            else:
                ax.loglog(x, y, marker=marker, color=colour, linestyle=line, label=text)
        ax.set_xlabel("mesh nodes")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    # dolfinx's import (a constant) beside its start-up.
    imports = [r for r in rows if r["code"] == "dolfinx" and r["mesh"] == "fissure"]
    if imports:
        ax_start.loglog([float(r["nodes"]) for r in imports],
                        [float(r["import_s"]) for r in imports], color="0.5", linestyle="--",
                        label="dolfinx: its import (not in start-up)")
    for name, rs in series.items():
        if name[0] != "dolfinx":
            continue
        colour, marker, line, text = style(name)
        ax_ratio.semilogx([float(r["nodes"]) for r in rs],
                          [fissure[r["target"]] / float(r["step_s"]) for r in rs],
                          marker=marker, color=colour, linestyle=line, label="Fissure / " + text)
    differences = [float(r["difference_to_fissure"]) for r in rows
                   if r["code"] == "dolfinx" and r["difference_to_fissure"]]
    ax_error.set_title("Fissure and dolfinx on Fissure's mesh coincide (to %.0e of the largest "
                       "temperature)" % max(differences, default=0.0), fontsize=9)
    ax_ratio.axhline(1.0, color="k", linewidth=0.8)
    ax_ratio.set_xlabel("mesh nodes")
    ax_ratio.set_ylabel("per-step time: Fissure / dolfinx (target <= 1)")
    ax_ratio.grid(True, which="both", alpha=0.3)
    ax_ratio.legend(fontsize=8)
    ax_step.legend(fontsize=8)
    ax_start.legend(fontsize=8)
    capacity = rows[0]["capacity"]
    fig.suptitle("Heat conduction in a square (P1, backward Euler, dt = 1000 s, "
                 f"{capacity} capacity, one core): Fissure and FEniCSx on the same mesh")
    fig.tight_layout()
    fig.savefig(here / "fenicsx_heat.png", dpi=100)
    print(f"wrote {here / 'fenicsx_heat.png'}")


if __name__ == "__main__":
    case = sys.argv[1] if len(sys.argv) > 1 else "both"
    if case in ("mandel", "both") and (here / "results.csv").exists():
        plot_mandel()
    if case in ("heat", "both") and (here / "results_heat.csv").exists():
        plot_heat()
