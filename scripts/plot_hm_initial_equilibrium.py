#!/usr/bin/python3
"""Pressures of a transient HM run with and without its initial stage
(docs/flow.md section 7, "Starting from equilibrium").

    scripts/plot_hm_initial_equilibrium.py WITH_STAGE WITHOUT_STAGE [-o PNG]

Reads results.h5 of both output folders (runs of
configs/flow_hm_injection_transient.yaml, the second with its
coupling.initial_equilibrium removed; a short output interval shows the
first steps) and draws, against time, the highest and lowest fracture
pressure and the pressure at the well (the node nearest (5, 5)), with the
physical bounds: absolute vacuum (-1.01e5 Pa gauge) and the overburden at the
model's base (rho_r g H = 2.6e5 Pa). Writes PNG (default
docs/img/flow_hm_initial_equilibrium.png).
"""
import argparse
from pathlib import Path

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

VACUUM = -1.01325e5
OVERBURDEN = 2650 * 9.81 * 10.0
WELL = (5.0, 5.0)


def history(folder):
    """Times, lowest, highest and well pressures (Pa) of every frame."""
    with h5py.File(Path(folder) / "results.h5", "r") as f:
        nodes = f["mesh/fractures/nodes"][:]
        well = int(np.argmin(np.hypot(nodes[:, 0] - WELL[0], nodes[:, 1] - WELL[1])))
        rows = []
        for name in sorted(f["frames"].keys()):
            frame = f["frames"][name]
            p = frame["fractures/pressure"][:]
            rows.append((frame.attrs["time"], p.min(), p.max(), p[well]))
    return np.array(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("with_stage")
    parser.add_argument("without_stage")
    parser.add_argument("-o", "--output", default=str(Path(__file__).resolve().parent.parent /
                                                      "docs" / "img" /
                                                      "flow_hm_initial_equilibrium.png"))
    a = parser.parse_args()
    fig, ax = plt.subplots(figsize=(8, 5.2))
    for folder, colour, label in ((a.with_stage, "tab:blue", "with the initial stage"),
                                  (a.without_stage, "tab:red", "without it")):
        h = history(folder)
        t = 1e3 * h[:, 0]
        ax.fill_between(t, h[:, 1] / 1e3, h[:, 2] / 1e3, color=colour, alpha=0.25,
                        label=f"{label}: lowest to highest pressure")
        ax.plot(t, h[:, 3] / 1e3, color=colour, lw=1.5, label=f"{label}: at the well")
    ax.axhline(OVERBURDEN / 1e3, color="k", ls="--", lw=1)
    ax.axhline(VACUUM / 1e3, color="k", ls=":", lw=1)
    ax.text(1.0, OVERBURDEN / 1e3, "overburden at the base ", va="bottom", ha="right", fontsize=8,
            transform=ax.get_yaxis_transform())
    ax.text(1.0, VACUUM / 1e3, "absolute vacuum ", va="top", ha="right", fontsize=8,
            transform=ax.get_yaxis_transform())
    ax.set_yscale("symlog", linthresh=100)
    ax.set_xlabel("t (ms)")
    ax.set_ylabel("fracture pressure (kPa)")
    ax.set_title("configs/flow_hm_injection_transient.yaml, first 50 ms", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2)
    fig.tight_layout()
    Path(a.output).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(a.output, dpi=90)
    print(a.output)


if __name__ == "__main__":
    main()
