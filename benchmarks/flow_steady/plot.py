#!/usr/bin/python3
"""Plots of benchmarks/flow_steady (docs/performance.md "flow_steady").

flow_steady.png           steady solve time against network size per back end
                          (first solve and repeated solve), and the split into
                          reduction / assembly / linear solve / the rest;
docs/img/flow_dfn_steady.png  the network of configs/flow_dfn_steady.yaml
                          coloured by head, line width by flux (docs/flow.md).
"""
import csv
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
IMG = HERE.parent.parent / "docs" / "img"


def rows(name):
    with open(HERE / name, newline="") as f:
        return list(csv.DictReader(f))


def timing():
    data = rows("results.csv")
    solvers = ["direct", "pcg", "petsc"]
    colours = {"direct": "tab:blue", "pcg": "tab:orange", "petsc": "tab:green"}
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    for s in solvers:
        for kind, style in (("first", "o-"), ("repeat", "s--")):
            r = [d for d in data if d["solver"] == s and d["solve_kind"] == kind]
            ax.plot([int(d["segments"]) for d in r], [float(d["total_s"]) for d in r], style,
                    color=colours[s], ms=4, label=f"{s}, {kind} solve")
    ax.axhline(1.0, color="k", ls=":", lw=1, label="target: 1 s at 1e5 segments")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("segments")
    ax.set_ylabel("steady solve wall time (s), one core")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Steady network solve")

    # The default back end (direct): share of each phase, per size and solve.
    parts = [("reduction_s", "reduction"), ("assembly_s", "assembly"), ("linear_s", "linear solve"),
             ("post_s", "fluxes, balance")]
    direct = [d for d in data if d["solver"] == "direct"]
    for x, d in enumerate(direct):
        total = sum(float(d[c]) for c, _ in parts)
        bottom = 0
        for k, (col, name) in enumerate(parts):
            v = 100 * float(d[col]) / total
            bx.bar(x, v, bottom=bottom, color=f"C{k}", label=name if x == 0 else None)
            bottom += v
        bx.text(x, 101, f"{1e3 * float(d['total_s']):.3g} ms", ha="center", fontsize=7)
    bx.set_xticks(range(len(direct)))
    bx.set_xticklabels([f"{int(d['segments']):.0e}\n{d['solve_kind']}" for d in direct], fontsize=7)
    bx.set_ylim(0, 110)
    bx.set_ylabel("share of the solve (%)")
    bx.set_xlabel("segments, solve")
    bx.set_title("direct (CHOLMOD): where the time goes")
    bx.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(HERE / "flow_steady.png", dpi=100)
    plt.close(fig)


def network():
    nodes = rows("network.csv")
    segs = rows("network_segments.csv")
    xy = [(float(n["x"]), float(n["y"])) for n in nodes]
    head = [float(n["head"]) for n in nodes]
    lines, colour, width = [], [], []
    q_max = max(abs(float(s["flux"])) for s in segs) or 1
    for s in segs:
        a, b = int(s["a"]), int(s["b"])
        lines.append([xy[a], xy[b]])
        colour.append(0.5 * (head[a] + head[b]))
        q = abs(float(s["flux"])) / q_max
        width.append(0.4 + 3.5 * max(0.0, 1 + math.log10(q) / 4) if q > 0 else 0.3)
    fig, ax = plt.subplots(figsize=(10, 5.4))
    flowing = [i for i, w in enumerate(width) if w > 0.3]
    still = [i for i, w in enumerate(width) if w <= 0.3]
    ax.add_collection(LineCollection([lines[i] for i in still], colors="0.75", linewidths=0.5))
    lc = LineCollection([lines[i] for i in flowing], array=[colour[i] for i in flowing],
                        cmap="viridis", linewidths=[width[i] for i in flowing])
    ax.add_collection(lc)
    fig.colorbar(lc, ax=ax, label="head (m)", shrink=0.8)
    ax.set_xlim(min(p[0] for p in xy) - 1, max(p[0] for p in xy) + 1)
    ax.set_ylim(min(p[1] for p in xy) - 1, max(p[1] for p in xy) + 1)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("configs/flow_dfn_steady.yaml: head 40 m (left) to 30 m (right); width ~ log |q|, "
                 "grey: no flow (dead ends, isolated)", fontsize=9)
    fig.tight_layout()
    IMG.mkdir(parents=True, exist_ok=True)
    fig.savefig(IMG / "flow_dfn_steady.png", dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    timing()
    if (HERE / "network.csv").exists():
        network()
