#!/usr/bin/python3
"""Plots of the dda_incline benchmark (docs/performance.md, section dda_incline).

    benchmarks/dda_incline/plot.py [results.csv]

Reads the CSV written by bench_dda_incline and writes, beside it:
  error_vs_walltime.png  |error of s(2 s)| against the wall time of the 2 s run
                         (best of 3), one line per penalty, points along dt;
  error_vs_dt.png        the incline (no dt dependence: Newmark is exact for a
                         constant acceleration) and the ramp and reversal
                         variants with their fitted order;
  error_vs_penalty.png   |error of s(1 s)| against the penalty, one line per dt,
                         the compliance prediction mu m g cos(alpha) / (p s) and
                         the window where every dt stays under 1 % shaded.
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SLOPE = math.radians(22.6)
G = 9.81
MASS = 2700 * 0.5  # kg per metre of thickness
FLOOR = 1e-16  # errors that are exactly zero are drawn here on log axes


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k not in ("problem", "status"):
                r[k] = float(v)
        r["ok"] = r["status"] == "completed" and not math.isnan(r["error_1s"])
    return rows


def usable(r):
    """Completed with the block still on the slope (a soft penalty lets it fall through)."""
    return r["ok"] and abs(r["sink_2s"]) < 0.25


def select(rows, **kw):
    return [r for r in rows if all(r[k] == v for k, v in kw.items())]


def absolute(e):
    return max(abs(e), FLOOR)


def penalty_colors(penalties):
    cmap = plt.get_cmap("viridis")
    lo, hi = math.log10(min(penalties)), math.log10(max(penalties))
    return {p: cmap((math.log10(p) - lo) / (hi - lo)) for p in penalties}


def sliding_acceleration(phi):
    return G * (math.sin(SLOPE) - math.cos(SLOPE) * math.tan(math.radians(phi)))


def plot_walltime(rows, out):
    inc = select(rows, problem="incline")
    phis = sorted({r["phi_deg"] for r in inc})
    # Every second decade, for legibility.
    pens = [p for p in sorted({r["penalty"] for r in inc})
            if abs(math.log10(p) - round(math.log10(p))) < 1e-9 and round(math.log10(p)) % 2 == 0]
    colors = penalty_colors(pens)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    for ax, phi in zip(axes.flat, phis):
        for p in pens:
            sub = sorted((r for r in select(inc, phi_deg=phi, penalty=p) if usable(r)),
                         key=lambda r: r["dt"])
            if not sub:
                continue
            ax.loglog([r["wall_seconds"] for r in sub], [absolute(r["error_2s"]) for r in sub],
                      "o-", ms=3, color=colors[p], label=f"p = {p:.0e} N/m")
        ax.axhline(0.01, color="k", ls=":", lw=1)
        ax.set_title(f"incline, phi = {phi:g} deg\n(points: dt = 2e-2 ... 1e-4 s, right = smaller)", fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("wall time of the 2 s run (s, best of 3)")
    for ax in axes[:, 0]:
        ax.set_ylabel("|relative error of s(2 s)|")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("DDA block on a 22.6 deg incline: error against wall time")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def fit_order(dts, errors):
    slope, _ = np.polyfit(np.log(dts), np.log(np.abs(errors)), 1)
    return slope


def plot_dt(rows, out):
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5))
    inc = select(rows, problem="incline", phi_deg=20.0)
    pens = [p for p in (1e7, 1e9, 1e11, 1e13, 1e18) if select(inc, penalty=p)]
    colors = penalty_colors(pens)
    for p in pens:
        sub = sorted((r for r in select(inc, penalty=p) if usable(r)), key=lambda r: r["dt"])
        left.loglog([r["dt"] for r in sub], [absolute(r["error_2s"]) for r in sub], "o-",
                    color=colors[p], label=f"p = {p:.0e} N/m")
    left.set_title("incline, phi = 20 deg: no order in dt (Newmark is exact for constant\n"
                   "acceleration): error = mu * sink / s + onset offsets at small dt\n"
                   "(contact dashpot while dt < 4 zeta / sqrt(p/m); sticking at stiff p)",
                   fontsize=10)
    left.set_xlabel("dt (s)")
    left.set_ylabel("|relative error of s(2 s)|")
    left.legend(fontsize=8)
    left.grid(True, which="major", alpha=0.3)

    variants = sorted({(r["problem"], r["penalty"]) for r in rows if r["problem"] != "incline"})
    for k, (problem, p) in enumerate(variants):
        style = ("s" if problem == "ramp" else "^") + ("-" if k % 2 == 0 else "--")
        sub = sorted((r for r in select(rows, problem=problem, penalty=p) if r["ok"]),
                     key=lambda r: r["dt"])
        dts = np.array([r["dt"] for r in sub])
        err = np.array([r["error_2s"] for r in sub])
        order = fit_order(dts, err)
        right.loglog(dts, np.abs(err), style, ms=4,
                     label=f"{problem}, p = {p:.0e}: order {order:.2f} "
                           f"(fit dt = {dts[0]:g} ... {dts[-1]:g})")
    ramp = select(rows, problem="ramp")
    if ramp:
        phi = ramp[0]["phi_deg"]
        dts = np.array(sorted({r["dt"] for r in ramp}))
        s2 = 0.5 * sliding_acceleration(phi) * 2**2 + 2**3 / 6  # s(2 s), jerk 1 m/s^3
        right.loglog(dts, 2 * (6 * dts + dts**2) / 12 / s2, "k:",
                     label="ramp, Newmark prediction j t (3 t dt + dt^2) / 12")
    right.set_title("acceleration changing in time (phi = 10 deg): first order", fontsize=10)
    right.set_xlabel("dt (s)")
    right.set_ylabel("|relative error of s(2 s)|")
    right.legend(fontsize=8)
    right.grid(True, which="major", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def window(rows, phi, pens):
    """Contiguous penalty range, around the best penalty, in which every dt is under 1 %."""
    good = []
    for p in pens:
        sub = select(rows, problem="incline", phi_deg=phi, penalty=p)
        good.append(bool(sub) and all(usable(r) and abs(r["error_1s"]) < 0.01 for r in sub))
    if not any(good):
        return None
    runs, start = [], None
    for k, g in enumerate(good + [False]):
        if g and start is None:
            start = k
        if not g and start is not None:
            runs.append((start, k - 1))
            start = None
    lo, hi = max(runs, key=lambda r: r[1] - r[0])
    return pens[lo], pens[hi]


def plot_penalty(rows, out):
    inc = select(rows, problem="incline")
    phis = sorted({r["phi_deg"] for r in inc})
    pens = sorted({r["penalty"] for r in inc})
    dts = sorted({r["dt"] for r in inc})
    cmap = plt.get_cmap("plasma")
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    for ax, phi in zip(axes.flat, phis):
        for k, dt in enumerate(dts):
            color = cmap(k / max(len(dts) - 1, 1) * 0.9)
            sub = sorted(select(inc, phi_deg=phi, dt=dt), key=lambda r: r["penalty"])
            ok = [r for r in sub if usable(r)]
            ax.loglog([r["penalty"] for r in ok], [absolute(r["error_1s"]) for r in ok], "o-",
                      ms=3, color=color, label=f"dt = {dt:g} s")
            bad = [r for r in sub if not usable(r)]
            ax.loglog([r["penalty"] for r in bad], [1.0] * len(bad), "x", color=color)
        mu = math.tan(math.radians(phi))
        s1 = 0.5 * sliding_acceleration(phi)
        p = np.array(pens)
        ax.loglog(p, mu * MASS * G * math.cos(SLOPE) / (p * s1), "k--", lw=1,
                  label="mu m g cos(a) / (p s): settled sink")
        ax.axhline(0.01, color="k", ls=":", lw=1)
        w = window(rows, phi, pens)
        if w:
            ax.axvspan(w[0], w[1], color="tab:green", alpha=0.12)
            ax.text(math.sqrt(w[0] * w[1]), 3e-2, f"< 1 % for all dt:\n{w[0]:.0e} ... {w[1]:.0e}",
                    ha="center", fontsize=8)
        ax.set_title(f"incline, phi = {phi:g} deg")
        ax.set_ylim(FLOOR / 10, 10)
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("normal penalty p (N/m)  [E = 1e10 Pa]")
    for ax in axes[:, 0]:
        ax.set_ylabel("|relative error of s(1 s)|  (x: fell through)")
    axes[0, 0].legend(fontsize=7, ncol=2)
    fig.suptitle("DDA block on a 22.6 deg incline: error against penalty")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("results.csv")
    rows = read(path)
    for name, plot in (("error_vs_walltime.png", plot_walltime), ("error_vs_dt.png", plot_dt),
                       ("error_vs_penalty.png", plot_penalty)):
        out = path.with_name(name)
        plot(rows, out)
        print(out)


if __name__ == "__main__":
    main()
