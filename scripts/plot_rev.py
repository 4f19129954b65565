#!/usr/bin/python3
"""Plots of a permeability REV study (`fissure rev`, docs/flow.md "REV study").

Reads OUTDIR/sizes.csv, fits.csv, domains.csv and rev.json and draws
  OUTDIR/rev_size.png   principal permeabilities against the domain size:
                        every realization, the mean with +-1 standard
                        deviation, the coefficient of variation and the
                        ellipse misfit against their criteria, the REV size;
  OUTDIR/rev_polar.png  directional permeability 1/sqrt(k(b)) of the
                        realizations at one size (default: the REV size, else
                        the largest), with the fitted tensor's ellipse
                        (theory.md 3.7 step 5: a tensor plots as an ellipse).

Usage: plot_rev.py OUTDIR [--size L]
"""
import argparse
import csv
import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def plot_sizes(out, sizes, fits, info):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    connected = [f for f in fits if f["connected"] > 0]
    for key, colour, label in (("k_max", "tab:blue", "$k_{max}$"), ("k_min", "tab:red", "$k_{min}$")):
        ax.scatter([f["size"] for f in connected], [f[key] for f in connected], s=8, color=colour,
                   alpha=0.35, lw=0)
        mean = [s[f"mean_{key.replace('_', '')}"] for s in sizes]
        std = [s[f"std_{key.replace('_', '')}"] for s in sizes]
        x = [s["size"] for s in sizes]
        ax.errorbar(x, mean, yerr=std, color=colour, marker="o", ms=4, capsize=3,
                    label=f"{label}: mean $\\pm$ 1 std")
    ax.set_yscale("log")
    ax.set_xlabel("domain size L (m)")
    ax.set_ylabel("permeability (m$^2$)")
    ax.grid(True, which="both", alpha=0.3)
    rev = info.get("rev_size")
    if rev is not None:
        ax.axvline(rev, color="k", ls="--", lw=1, label=f"REV size {rev:.3g} m")
    ax.legend(fontsize=8)
    ax.set_title(f"{info['name']}: {int(info['config']['realizations'])} realizations per size")

    x = [s["size"] for s in sizes]
    bx.plot(x, [s["cv_kmax"] for s in sizes], "o-", color="tab:blue", ms=4, label="CV($k_{max}$)")
    bx.plot(x, [s["cv_kmin"] for s in sizes], "o-", color="tab:red", ms=4, label="CV($k_{min}$)")
    bx.plot(x, [s["mean_misfit"] for s in sizes], "s-", color="tab:green", ms=4,
            label="mean ellipse misfit")
    bx.axhline(info["config"]["cv_max"], color="tab:purple", ls=":", label="cv_max")
    bx.axhline(info["config"]["misfit_max"], color="tab:olive", ls="--", label="misfit_max")
    if rev is not None:
        bx.axvline(rev, color="k", ls="--", lw=1)
    bx.set_yscale("log")
    bx.set_xlabel("domain size L (m)")
    bx.set_ylabel("coefficient of variation, misfit (-)")
    bx.grid(True, which="both", alpha=0.3)
    bx.legend(fontsize=8)
    bx.set_title("REV criterion")
    fig.tight_layout()
    fig.savefig(out / "rev_size.png", dpi=110)
    plt.close(fig)


def plot_polar(out, size, domains, fits):
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="polar")
    rows = [d for d in domains if abs(d["size"] - size) < 1e-9 * max(1.0, size) and d["connected"] > 0]
    realizations = sorted({int(d["realization"]) for d in rows})
    colours = plt.cm.viridis([i / max(1, len(realizations) - 1) for i in range(len(realizations))])
    for colour, r in zip(colours, realizations):
        mine = [d for d in rows if int(d["realization"]) == r]
        # Each rotated square measures k along its x axis (b) and its y axis (b + 90 deg).
        angles, radii = [], []
        for d in mine:
            b = math.radians(d["rotation_deg"])
            for a, k in ((b, d["kxx"]), (b + math.pi / 2, d["kyy"])):
                if k > 0:
                    for turn in (0, math.pi):  # k(b) = k(b + 180 deg)
                        angles.append(a + turn)
                        radii.append(1 / math.sqrt(k))
        ax.scatter(angles, radii, s=10, color=colour, zorder=3)
        fit = [f for f in fits if abs(f["size"] - size) < 1e-9 * max(1.0, size)
               and int(f["realization"]) == r]
        if fit and fit[0]["k_min"] > 0:
            f = fit[0]
            t = [2 * math.pi * i / 360 for i in range(361)]
            kg = [f["k11"] * math.cos(a) ** 2 + 2 * f["k12"] * math.sin(a) * math.cos(a)
                  + f["k22"] * math.sin(a) ** 2 for a in t]
            ax.plot(t, [1 / math.sqrt(k) for k in kg], color=colour, lw=1)
    ax.set_title(f"1/sqrt(k) (m$^{{-1}}$) at L = {size:.3g} m: measured (dots), fitted tensor "
                 "(lines)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "rev_polar.png", dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", type=pathlib.Path)
    parser.add_argument("--size", type=float, help="domain size of the polar plot (m)")
    args = parser.parse_args()
    out = args.outdir
    info = json.loads((out / "rev.json").read_text())
    sizes = read_csv(out / "sizes.csv")
    fits = read_csv(out / "fits.csv")
    domains = read_csv(out / "domains.csv")
    plot_sizes(out, sizes, fits, info)
    size = args.size or info.get("rev_size") or sizes[-1]["size"]
    plot_polar(out, size, domains, fits)


if __name__ == "__main__":
    main()
