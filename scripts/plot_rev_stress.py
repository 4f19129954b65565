#!/usr/bin/python3
"""Plots of a REV study under stress (`fissure rev` with a mechanics section,
docs/upscaling.md).

Reads OUTDIR/stress_states.csv and stress.json and draws OUTDIR/rev_stress.png:
  (a) k_max and k_min of the largest squares (mean +- 1 standard deviation
      over the realizations at rest) against the mean effective stress, one
      line per stress ratio that several states share (Min et al. 2004's
      first series);
  (b) the same against sigma_1 / sigma_3, one line per sigma_3 that several
      states share (their second series);
  (c) the share of slipping contacts and of squares at rest against the
      ratio;
  (d) k_max against the square's size for every state (the REV check);
  and, where the study measured the compliance, (e) the moduli E_1 (along
  sigma_1), E_3 and the shear modulus G_13 of the largest squares against
  the mean stress and (f)
  against the ratio.

Usage: plot_rev_stress.py OUTDIR
"""
import argparse
import csv
import json
import math
import pathlib
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(v):
    return float(v) if v != "" else math.nan


def read_rows(path):
    with open(path, newline="") as f:
        return [{k: number(v) for k, v in row.items()} for row in csv.DictReader(f)]


def series(rows, key, digits=3):
    """Rows grouped by the rounded value of `key`, groups of two or more."""
    groups = defaultdict(list)
    for r in rows:
        if not math.isnan(r[key]):
            groups[round(r[key], digits)].append(r)
    return {k: v for k, v in sorted(groups.items()) if len(v) >= 2}


def draw_k(ax, groups, x_key, label_of, colours):
    for (value, rows), colour in zip(groups.items(), colours):
        rows = sorted(rows, key=lambda r: r[x_key])
        for key, marker, fill in (("kmax", "o", colour), ("kmin", "s", "none")):
            pts = [r for r in rows if r[f"mean_{key}"] > 0]
            if not pts:
                continue
            ax.errorbar([r[x_key] for r in pts], [r[f"mean_{key}"] for r in pts],
                        yerr=[r[f"std_{key}"] for r in pts], color=colour, marker=marker,
                        mfc=fill, ms=5, capsize=3,
                        label=f"{'$k_{max}$' if key == 'kmax' else '$k_{min}$'}, {label_of(value)}")
    ax.set_yscale("log")
    ax.set_ylabel("permeability (m$^2$)")
    ax.grid(True, which="both", alpha=0.3)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("outdir")
    args = parser.parse_args()
    out = pathlib.Path(args.outdir)
    rows = read_rows(out / "stress_states.csv")
    info = json.loads((out / "stress.json").read_text())
    largest = max(r["size"] for r in rows)
    top = [r for r in rows if r["size"] == largest]
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]

    moduli = any(not math.isnan(r.get("mean_E_1", math.nan)) for r in top)
    fig, axes = plt.subplots(2, 3 if moduli else 2, figsize=(17 if moduli else 12, 9))
    if moduli:
        (ax, bx, ex), (cx, dx, fx) = axes
    else:
        (ax, bx), (cx, dx) = axes
    draw_k(ax, series(top, "ratio"), "mean_MPa", lambda v: f"$\\sigma_1/\\sigma_3$ = {v:g}",
           colours)
    ax.set_xlabel("mean effective stress $(\\sigma_1' + \\sigma_3')/2$ (MPa)")
    ax.set_title(f"(a) stress magnitude, L = {largest:g} m")
    ax.legend(fontsize=7)

    draw_k(bx, series(top, "sigma_3_MPa"), "ratio",
           lambda v: f"$\\sigma_3'$ = {v:g} MPa", colours)
    failed = [r["ratio"] for r in top if r["mean_kmax"] <= 0 and not math.isnan(r["ratio"])]
    for x in failed:
        bx.axvline(x, color="tab:gray", ls=":", lw=1)
    if failed:
        bx.text(0.98, 0.02, "dotted: no square at rest (the joints slide)", transform=bx.transAxes,
                ha="right", va="bottom", fontsize=7, color="tab:gray")
    bx.set_xlabel("stress ratio $\\sigma_1/\\sigma_3$")
    bx.set_title(f"(b) stress ratio, L = {largest:g} m")
    bx.legend(fontsize=7)

    by_ratio = sorted((r for r in top if not math.isnan(r["ratio"])), key=lambda r: r["ratio"])
    cx.plot([r["ratio"] for r in by_ratio], [r["slip_fraction"] for r in by_ratio], "o",
            color="tab:red", label="share of closed contacts that slip")
    cx.plot([r["ratio"] for r in by_ratio], [r["equilibrium_fraction"] for r in by_ratio], "s",
            color="tab:green", mfc="none", label="share of squares at rest")
    cx.set_xlabel("stress ratio $\\sigma_1/\\sigma_3$")
    cx.set_ylim(-0.05, 1.05)
    cx.grid(True, alpha=0.3)
    cx.legend(fontsize=8)
    cx.set_title(f"(c) slip and equilibrium, L = {largest:g} m")

    states = defaultdict(list)
    for r in rows:
        states[int(r["state"])].append(r)
    for (state, rs), colour in zip(sorted(states.items()), colours * 4):
        rs = [r for r in sorted(rs, key=lambda r: r["size"]) if r["mean_kmax"] > 0]
        if not rs:
            continue
        dx.plot([r["size"] for r in rs], [r["mean_kmax"] for r in rs], "o-", ms=3, color=colour,
                label=f"{rs[0]['sigma_1_MPa']:g} / {rs[0]['sigma_3_MPa']:g} MPa")
    dx.set_yscale("log")
    dx.set_xlabel("square size L (m)")
    dx.set_ylabel("mean $k_{max}$ (m$^2$)")
    dx.grid(True, which="both", alpha=0.3)
    dx.legend(fontsize=7, title="$\\sigma_1'$ / $\\sigma_3'$", title_fontsize=7)
    dx.set_title("(d) size dependence")
    if moduli:
        for axis, key, groups, label_of, xlabel, title in (
                (ex, "mean_MPa", series(top, "ratio"), lambda v: f"$\\sigma_1/\\sigma_3$ = {v:g}",
                 "mean effective stress (MPa)", "(e) moduli against the magnitude"),
                (fx, "ratio", series(top, "sigma_3_MPa"), lambda v: f"$\\sigma_3'$ = {v:g} MPa",
                 "stress ratio $\\sigma_1/\\sigma_3$", "(f) moduli against the ratio")):
            for (value, rs), colour in zip(groups.items(), colours):
                rs = sorted((r for r in rs if not math.isnan(r["mean_E_1"])), key=lambda r: r[key])
                if not rs:
                    continue
                for name, marker, fill in (("E_1", "o", colour), ("E_3", "s", "none"),
                                           ("G_13", "^", "none")):
                    if f"mean_{name}" not in rs[0]:  # a study from before the shear term
                        continue
                    axis.errorbar([r[key] for r in rs], [r[f"mean_{name}"] / 1e9 for r in rs],
                                  yerr=[r[f"std_{name}"] / 1e9 for r in rs], color=colour,
                                  marker=marker, mfc=fill, ms=5, capsize=3,
                                  label=f"${name.replace('_13', '_{13}')}$, {label_of(value)}")
            axis.set_xlabel(xlabel)
            axis.set_ylabel("modulus (GPa)")
            axis.grid(True, alpha=0.3)
            axis.legend(fontsize=7)
            axis.set_title(f"{title}, L = {largest:g} m")
    fig.suptitle(f"{info.get('name', '')}: permeability under stress")
    fig.tight_layout()
    fig.savefig(out / "rev_stress.png", dpi=120)


if __name__ == "__main__":
    main()
