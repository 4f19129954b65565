#!/usr/bin/env python3
"""Plots of bench_continuum_accuracy's CSV files (docs/continuum.md 6):
verification.png (Terzaghi's profiles and Mandel's pressures against the
series), orders.png (L2 errors in mesh size and step), work_precision.png
(error against wall time, Mandel), booker_savvidou.png (the point heat
source's errors against unknowns and steps), fixed_stress.png (passes against the factor),
first_step.png (Taylor-Hood and P1/P1 after one short step) and
stability.png (fixed-stress passes over permeability and step).
Usage: plot.py (after bench_continuum_accuracy), with Debian's matplotlib."""
import csv
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = Path(__file__).parent


def rows(name):
    with open(HERE / name) as f:
        return list(csv.DictReader(f))


def verification():
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.6))
    profiles = rows("terzaghi_profiles.csv")
    for i, tv in enumerate(sorted({r["time_factor"] for r in profiles}, key=float)):
        part = [r for r in profiles if r["time_factor"] == tv]
        z = [float(r["depth"]) for r in part]
        left.plot([float(r["exact"]) for r in part], z, "-", color=f"C{i}", lw=1.2,
                  label=f"T_v = {tv}: series")
        left.plot([float(r["p_over_p0"]) for r in part][::2], z[::2], "o", color=f"C{i}", ms=3.5,
                  label="FEM (1 x 40 cells)" if i == 0 else None)
    left.invert_yaxis()
    left.set_xlabel("p / p0")
    left.set_ylabel("depth below the drained top z (m)")
    left.set_title("Terzaghi: pressure profiles")
    left.legend(fontsize="small")
    curves = rows("mandel_curves.csv")
    t = [float(r["ct_a2"]) for r in curves]
    for key, name, colour in (("centre", "x = 0", "C0"), ("half", "x = a/2", "C1")):
        right.plot(t, [float(r[f"{key}_exact"]) for r in curves], "-", color=colour, lw=1.2,
                   label=f"{name}: series")
        right.plot(t[::4], [float(r[key]) for r in curves][::4], "o", color=colour, ms=3.5,
                   label=f"{name}: FEM (16 x 16)")
    right.axhline(1.0, color="0.5", lw=0.6, ls=":")
    right.set_xscale("log")
    right.set_xlim(0.01, 1.5)
    right.set_xlabel("c t / a^2")
    right.set_ylabel("p / p0")
    right.set_title("Mandel: the Mandel-Cryer rise above p0")
    right.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "verification.png", dpi=130)


def orders():
    data = rows("mandel_orders.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    space = [r for r in data if r["study"] == "space"]
    h = [1 / float(r["n"]) for r in space]
    for key, name, slope in (("error_p", "pressure (P1)", 2), ("error_u", "displacement (P2)", 2)):
        e = [float(r[key]) for r in space]
        left.loglog(h, e, "o-", label=name)
    ref = [float(space[0]["error_p"]) * (x / h[0]) ** 2 for x in h]
    left.loglog(h, ref, "k--", lw=0.8, label="slope 2")
    left.set_xlabel("h (m)")
    left.set_ylabel("relative L2 error at c t / a^2 = 0.1")
    left.set_title("Mandel: mesh size (dt = 1e-3 s)")
    left.legend(fontsize="small")
    time = [r for r in data if r["study"] == "time"]
    dt = [float(r["dt"]) for r in time]
    for key, name in (("error_p", "pressure"), ("error_u", "displacement")):
        right.loglog(dt, [float(r[key]) for r in time], "o-", label=name)
    right.loglog(dt, [float(time[0]["error_p"]) * x / dt[0] for x in dt], "k--", lw=0.8,
                 label="slope 1")
    right.set_xlabel("dt (s)")
    right.set_ylabel("relative L2 difference from dt = 1.25e-3 s")
    right.set_title("Mandel: step, backward Euler (16 x 16)")
    right.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "orders.png", dpi=130)


def work_precision():
    data = rows("mandel_work_precision.csv")
    fig, ax = plt.subplots(figsize=(6.5, 4.6))
    for scheme in ("monolithic", "fixed_stress"):
        part = [r for r in data if r["scheme"] == scheme]
        ax.loglog([float(r["seconds"]) for r in part], [float(r["error"]) for r in part], "o-",
                  label=scheme)
        for r in part:
            ax.annotate(f"n={r['n']}", (float(r["seconds"]), float(r["error"])), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
    ax.axhline(0.02, color="0.5", ls=":", lw=0.8, label="catalogue tolerance (2 % p0)")
    ax.set_xlabel("wall time (s), to c t / a^2 = 0.2")
    ax.set_ylabel("largest nodal |p - p_exact| / p0")
    ax.set_title("Mandel: mesh and step refined together")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "work_precision.png", dpi=130)


def booker_savvidou():
    # Error against a deterministic cost, the unknowns or the steps: the wall
    # times (in the CSV) were taken on a shared machine.
    data = rows("booker_savvidou_work_precision.csv")
    studies = (("source", "h_f at the source (grading 0.15)", "fine_m", "m", "unknowns"),
               ("grading", "the grading (h_f = 5 cm)", "grading", "", "unknowns"),
               ("step", "dt (h_f = 5 cm, grading 0.15)", "dt_years", "yr", "steps"))
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    for ax, (study, what, key_of_note, unit, cost) in zip(axes, studies):
        # The grading study continues from the finest source row.
        part = [r for r in data if r["study"] == study]
        if study == "grading":
            part = [r for r in data if r["study"] == "source"][-1:] + part
        if not part:
            continue
        x = [float(r["unknowns"]) if cost == "unknowns" else 1 / float(r["dt_years"]) for r in part]
        for key, name in (("error_T", "Delta T"), ("error_p", "p")):
            ax.loglog(x, [float(r[key]) for r in part], "o-", label=name)
        for xi, r in zip(x, part):
            ax.annotate(f"{float(r[key_of_note]):g} {unit}", (xi, float(r["error_T"])), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        ax.axhline(0.02, color="0.5", ls=":", lw=0.8, label="test tolerance of Delta T (2 %)")
        ax.set_xlabel("unknowns" if cost == "unknowns" else "steps in the year")
        ax.set_ylabel("largest relative error at r = 1, 2, 4 m")
        ax.set_title(f"Booker-Savvidou: refining {what}", fontsize=9)
        ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "booker_savvidou.png", dpi=130)

def fixed_stress():
    data = [r for r in rows("fixed_stress.csv") if r["passes_per_step"] != "nan"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot([float(r["factor"]) for r in data], [float(r["passes_per_step"]) for r in data], "o-")
    ax.axvline(0.5, color="0.5", ls=":", lw=0.8, label="0.5: Mikelic and Wheeler's sufficient bound")
    ax.set_xlabel("fixed_stress_factor (beta_FS = factor alpha^2 / K_dr)")
    ax.set_ylabel("passes per step to 1e-10")
    ax.set_title("Fixed stress on Mandel (tau = 2.88); at factor 0.25 it diverges")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "fixed_stress.png", dpi=130)


def first_step():
    data = rows("first_step.csv")
    fig, ax = plt.subplots(figsize=(6.8, 4.8))
    ref = [r for r in data if r["elements"] == "taylor_hood" and r["stabilization"] == "0"]
    ax.plot([float(r["exact"]) for r in ref], [float(r["depth"]) for r in ref], "k-", lw=1.4,
            label="series")
    for name, label, colour in (("taylor_hood", "Taylor-Hood P2/P1", "C0"),
                                ("p1p1", "equal order P1/P1", "C2")):
        for stab, style, width in (("0", "--", 1.0), ("1", "-", 2.4 if name == "taylor_hood" else 1.0)):
            part = [r for r in data if r["elements"] == name and r["stabilization"] == stab]
            ax.plot([float(r["p_over_p0"]) for r in part], [float(r["depth"]) for r in part],
                    style, color=colour, lw=width,
                    label=f"{label}, " + ("no stabilization (default)" if stab == "0"
                                         else "pressure_stabilization: 1"))
    ax.set_ylim(2.0, 0)
    ax.axvline(1.0, color="0.5", lw=0.6, ls=":")
    ax.set_xlabel("p / p0 (along x = 0.5 m)")
    ax.set_ylabel("depth below the drained top z (m)")
    ax.set_title("Terzaghi after one step of 1 s (c dt / h^2 = 0.017): the elements\n"
                 "overshoot; the stabilization is monotone but smears the layer")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(HERE / "first_step.png", dpi=130)


def stability():
    data = rows("stability.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11.5, 4.6))
    for i, k in enumerate(sorted({r["permeability"] for r in data}, key=float)):
        for stab, style, axis in (("0", "o-", right), ("1", "s--", right)):
            part = [r for r in data if r["permeability"] == k and r["stabilization"] == stab]
            dt = [float(r["dt"]) for r in part]
            if stab == "0":
                left.semilogx(dt, [float(r["passes_per_step"]) for r in part], "o-",
                              color=f"C{i}", ms=3.5, label=f"k = {float(k):.0e} m^2")
            axis.semilogx(dt, [float(r["p_max"]) for r in part], style, color=f"C{i}", ms=3,
                          lw=0.9, label=(f"k = {float(k):.0e}" if stab == "0" else None))
    left.set_xlabel("dt (s)")
    left.set_ylabel("fixed-stress passes per step to 1e-10")
    left.set_title("Terzaghi's column: fixed stress over k and dt")
    left.legend(fontsize="x-small", ncol=2)
    right.axhline(1.02, color="0.4", ls=":", lw=0.8)
    right.set_xlabel("dt (s)")
    right.set_ylabel("largest p / p0 after 5 steps")
    right.set_title("overshoot: circles unstabilized, squares stabilized")
    right.legend(fontsize="x-small", ncol=2)
    fig.tight_layout()
    fig.savefig(HERE / "stability.png", dpi=130)


if __name__ == "__main__":
    verification()
    orders()
    work_precision()
    booker_savvidou()
    fixed_stress()
    first_step()
    stability()
    print("wrote", ", ".join(p.name for p in sorted(HERE.glob("*.png"))))
