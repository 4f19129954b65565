#!/usr/bin/python3
"""Plots of benchmarks/hm_step_cost (docs/performance.md "hm_step_cost").

hm_step_cost.png                cost per DDA step: mechanics alone and the
                                coupled variants, split into mechanics and flow;
docs/img/flow_hm_injection.png  configs/flow_hm_injection.yaml: blocks and
                                fractures at the end (pressure, aperture) and
                                the history at the well (docs/flow.md).
"""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
IMG = HERE.parent.parent / "docs" / "img"


def rows(name):
    with open(HERE / name, newline="") as f:
        return list(csv.DictReader(f))


def cost():
    data = rows("results.csv")
    sizes = sorted({int(d["blocks"]) for d in data})
    fig, axes = plt.subplots(1, len(sizes), figsize=(5 * len(sizes), 3.8), squeeze=False)
    for ax, n in zip(axes[0], sizes):
        r = [d for d in data if int(d["blocks"]) == n]
        x = range(len(r))
        mech = [1e3 * float(d["mechanics_per_step_s"]) for d in r]
        flow = [1e3 * float(d["flow_per_step_s"]) for d in r]
        wall = [1e3 * float(d["wall_per_step_s"]) for d in r]
        ax.bar(x, mech, color="tab:blue", label="mechanics (DDA)")
        ax.bar(x, flow, bottom=mech, color="tab:cyan", label="flow")
        ax.plot(x, wall, "k_", ms=20, mew=2, label="wall")
        for i, d in enumerate(r):
            ax.text(i, wall[i], f"x{float(d['ratio_to_mechanics']):.2f}", ha="center", va="bottom",
                    fontsize=8)
        ax.set_xticks(list(x))
        ax.set_xticklabels([d["case"].replace("_", "\n") for d in r], fontsize=8)
        ax.set_ylabel("ms per DDA step")
        ax.set_title(f"{n} blocks")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(HERE / "hm_step_cost.png", dpi=100)
    plt.close(fig)


def injection():
    blocks = rows("final_blocks.csv")
    net = rows("final_network.csv")
    hist = rows("history.csv")
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw={"width_ratios": [1.1, 1]})
    polys = {}
    fixed = {}
    for b in blocks:
        polys.setdefault(int(b["block"]), []).append((float(b["x"]), float(b["y"])))
        fixed[int(b["block"])] = b["fixed"] == "1"
    ax.add_collection(PolyCollection(list(polys.values()),
                                     facecolors=["0.85" if fixed[k] else "0.95" for k in polys],
                                     edgecolors="0.6", linewidths=0.3))
    lines = [[(float(s["xa"]), float(s["ya"])), (float(s["xb"]), float(s["yb"]))] for s in net]
    p = [0.5 * (float(s["pa"]) + float(s["pb"])) / 1e3 for s in net]
    e = [float(s["aperture"]) for s in net]
    e_min = min(e)
    lc = LineCollection(lines, array=p, cmap="plasma", linewidths=[1 + 5 * (x / e_min - 1) ** 0.5
                                                                   for x in e])
    ax.add_collection(lc)
    fig.colorbar(lc, ax=ax, label="pressure (kPa)", shrink=0.8)
    ax.plot([5], [5], "kv", ms=8)
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("t = 0.5 s: pressure; line width ~ aperture (fixed blocks grey)", fontsize=9)
    t = [float(h["t"]) for h in hist]
    bx.plot(t, [float(h["well_pressure"]) / 1e3 for h in hist], "o-", color="tab:red",
            label="pressure at the well (kPa)")
    bx.set_xlabel("t (s)")
    bx.set_ylabel("pressure at the well (kPa)", color="tab:red")
    cx = bx.twinx()
    cx.plot(t, [1e6 * float(h["max_aperture"]) for h in hist], "s-", color="tab:blue",
            label="largest aperture (um)")
    cx.plot(t, [1e6 * float(h["uplift"]) for h in hist], "^-", color="tab:green",
            label="uplift above the well (um)")
    cx.set_ylabel("aperture, uplift (um)")
    h1, l1 = bx.get_legend_handles_labels()
    h2, l2 = cx.get_legend_handles_labels()
    bx.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
    bx.set_title("history (injection ramped up over 0.2 s)", fontsize=9)
    bx.grid(True, alpha=0.3)
    fig.tight_layout()
    IMG.mkdir(parents=True, exist_ok=True)
    fig.savefig(IMG / "flow_hm_injection.png", dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    cost()
    if (HERE / "history.csv").exists():
        injection()
