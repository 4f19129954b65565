#!/usr/bin/python3
"""Lauwerier's single fracture (verification.md (i), docs/thermal.md 7): the
water's temperature along the fracture at t = 1e6 s on two meshes against
the closed form.

    scripts/plot_lauwerier.py DIR [-o PNG]

DIR holds lauwerier_h0.5.csv and lauwerier_h0.25.csv (x, theta_f, lauwerier),
written by the test verification.ThermalFractureConvection.Lauwerier_i into
build/test-output/thermal_fracture_convection/ThermalFractureConvection.Lauwerier_i.
Writes PNG (default docs/img/lauwerier.png).
"""
import argparse
from pathlib import Path

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TABLE_X = [2, 5, 10, 15]
TABLE_THETA = [0.86671, 0.67474, 0.40118, 0.20782]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("dir", type=Path)
    p.add_argument("-o", "--output", type=Path,
                   default=Path(__file__).resolve().parent.parent / "docs/img/lauwerier.png")
    a = p.parse_args()
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [2, 1]})
    exact = None
    for h, style in (("0.5", "o-"), ("0.25", "s-")):
        d = np.genfromtxt(a.dir / f"lauwerier_h{h}.csv", delimiter=",", names=True)
        exact = d
        top.plot(d["x"], d["theta_f"], style, ms=2.5, lw=1, label=f"Fissure, h = {h} m")
        bottom.plot(d["x"], d["theta_f"] - d["lauwerier"], style, ms=2.5, lw=1,
                    label=f"h = {h} m")
    top.plot(exact["x"], exact["lauwerier"], "k-", lw=1.5, label="Lauwerier (closed form)")
    top.plot(TABLE_X, TABLE_THETA, "kx", ms=8, label="verification.md (i) table")
    top.set_ylabel(r"$\theta_f = (T_f - T_0) / (T_{in} - T_0)$")
    top.set_title("Lauwerier: the water along the fracture at t = 1e6 s\n"
                  "(v = 0.01 m/s, b = 1 mm, wall temperature, rock conducting across only)",
                  fontsize=10)
    top.legend()
    top.grid(alpha=0.3)
    bottom.axhline(0, color="k", lw=0.8)
    for s in (-0.02, 0.02):
        bottom.axhline(s, color="r", ls="--", lw=0.8)
    bottom.set_ylim(-0.025, 0.025)
    bottom.set_xlabel("x (m)")
    bottom.set_ylabel("error (tolerance dashed)")
    bottom.legend()
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    print(a.output)


if __name__ == "__main__":
    main()
