#!/usr/bin/python3
"""The DECOVALEX chain of docs/upscaling.md section 8 in one command: the
Sellafield-like DFN's permeability under the in-situ stresses
(configs/sellafield_stress_study.yaml, `fissure rev`), then the far field
that takes its table (configs/sellafield_far_field.yaml, `fissure run`),
then the chain's pictures.

  OUT/sellafield_stress_study/   the study (stress_states.csv, stress.json, rev_stress.png)
  OUT/sellafield_far_field.yaml  the far-field scene, beside its study
  OUT/far_field/                 the far field's run (results.xdmf, monitors.csv, ...)
  OUT/unheated/                  the same far field without the repository's heat
  OUT/chain_k_stress.png         k_max, k_min of the study against the mean effective
                                 stress and depth, with the table the far field uses
  OUT/chain_far_field.png        what the heat does at 100 and 1,000 years: the
                                 temperature change, and the pressure and permeability
                                 against the unheated run's (which hold the recharge's
                                 regional flow and its own change of k)

--quick runs the small variant (1 realization, 3 of the 5 depths, 5 far-field steps;
about 30 s), as make test's CI lines do.

Usage: run_sellafield_chain.py [--fissure build/app/fissure] [--output out/sellafield_chain]
                               [--quick]
"""
import argparse
import csv
import pathlib
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fissure_results import complete_frames  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
YEAR = 365.25 * 86400
# The far field's effective stress gradients (configs/sellafield_far_field.yaml):
# sigma'_m = ((31.181 + 25.997) / 2 - 9.81) kPa/m * depth.
MEAN_EFFECTIVE_PER_M = (31181 + 25997) / 2 - 9810


def run(command):
    print("+", " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], check=True, cwd=ROOT)


def draw_k_stress(study, png):
    """k_max, k_min of the largest squares (mean +- std over the realizations)
    against sigma'_m, with the table (log-linear between the states)."""
    with open(study / "stress_states.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    largest = max(float(r["size"]) for r in rows)
    rows = [r for r in rows if float(r["size"]) == largest and float(r["mean_kmax"]) > 0]
    rows.sort(key=lambda r: float(r["mean_MPa"]))
    s = np.array([float(r["mean_MPa"]) for r in rows])
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for key, label, colour in (("kmax", "k_max", "C0"), ("kmin", "k_min", "C1")):
        k = np.array([float(r["mean_" + key]) for r in rows])
        sd = np.array([float(r["std_" + key]) for r in rows])
        ax.errorbar(s, k, yerr=sd, fmt="o", color=colour, capsize=3,
                    label=f"{label} of the {largest:g} m squares (mean ± std)")
        fine = np.linspace(0, s.max() * 1.05, 200)
        table = np.exp(np.interp(fine, s, np.log(k)))
        ax.plot(fine, table, "-", color=colour, lw=1,
                label=f"{label} of the far field's table (held beyond the states)")
    ax.set_yscale("log")
    ax.set_xlabel("mean effective stress σ'_m (MPa)")
    ax.set_ylabel("permeability (m²)")
    top = ax.secondary_xaxis("top", functions=(lambda m: m * 1e6 / MEAN_EFFECTIVE_PER_M,
                                               lambda d: d * MEAN_EFFECTIVE_PER_M / 1e6))
    top.set_xlabel("depth in the far field (m)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="lower left")
    ax.set_title("Sellafield-like DFN under the in-situ stresses (ratio 1.32)", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)


def frames_near(results, times):
    """(mesh triangulation, [(time, fields)]) of the frames nearest `times`."""
    import h5py
    with h5py.File(results, "r") as h5:
        frames = complete_frames(h5)
        x = h5["mesh/continuum_vertices"][...]
        tri = mtri.Triangulation(x[:, 0], x[:, 1], h5["mesh/continuum_triangles"][...])
        picked = []
        for t in times:
            time, group = min(frames, key=lambda f: abs(f[0] - t))
            c = group["continuum"]
            picked.append((time, {n: c[n][...] for n in
                                  ("temperature_change", "pressure", "permeability")}))
    return tri, picked


def draw_far_field(heated, unheated, png):
    """At the frames nearest 100 and 1,000 years: the temperature change, and
    the pore pressure and log10 k of the heated run against the unheated."""
    times = [100 * YEAR, 1000 * YEAR]
    tri, picked = frames_near(heated, times)
    _, reference = frames_near(unheated, times)
    for (_, values), (_, base) in zip(picked, reference):
        values["heat_pressure"] = values["pressure"] - base["pressure"]
        values["heat_permeability"] = np.log10(values["permeability"] / base["permeability"])
    fig, axes = plt.subplots(3, len(picked), figsize=(6.2 * len(picked), 8.4), squeeze=False)
    fields = (("temperature_change", "temperature change (K)", "Reds", 1),
              ("heat_pressure", "pore pressure from the heat (kPa)", "RdBu_r", 1e-3),
              ("heat_permeability", "log10(k / k unheated)", "RdBu_r", 1))
    for col, (time, values) in enumerate(picked):
        for row, (name, label, cmap, scale) in enumerate(fields):
            ax = axes[row][col]
            v = values[name] * scale
            big = max(float(np.abs(v).max()), 1e-12)
            if name == "heat_permeability":  # per triangle
                image = ax.tripcolor(tri, facecolors=v, cmap=cmap, vmin=-big, vmax=big)
            elif cmap == "RdBu_r":  # white at zero
                image = ax.tripcolor(tri, v, cmap=cmap, shading="gouraud", vmin=-big, vmax=big)
            else:
                image = ax.tripcolor(tri, v, cmap=cmap, shading="gouraud", vmin=0, vmax=big)
            fig.colorbar(image, ax=ax, label=label, fraction=0.03, pad=0.02)
            ax.set_aspect("equal")
            ax.set_title(f"{label} at {time / YEAR:.0f} years", fontsize=9)
            ax.set_xlabel("x (m)")
            ax.set_ylabel("y (m)")
    fig.suptitle("Sellafield-like far field: what the repository's heat does to a fractured rock "
                 "that takes the study's k(σ')", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--fissure", default=str(ROOT / "build" / "app" / "fissure"))
    parser.add_argument("--output", default=str(ROOT / "out" / "sellafield_chain"))
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    out = pathlib.Path(args.output).resolve()
    fissure = pathlib.Path(args.fissure).resolve()
    out.mkdir(parents=True, exist_ok=True)
    study = out / "sellafield_stress_study"
    quick_study = ["--realizations", "1", "--states", "0,2,4"] if args.quick else []
    run([fissure, "rev", ROOT / "configs" / "sellafield_stress_study.yaml",
         "--output", study] + quick_study)
    # The far field reads its study beside it (sellafield_stress_study/stress.json).
    scene = out / "sellafield_far_field.yaml"
    shutil.copyfile(ROOT / "configs" / "sellafield_far_field.yaml", scene)
    quick_far = ["--max-steps", "5"] if args.quick else []
    run([fissure, "run", scene, "--output", out / "far_field"] + quick_far)
    # The same without the heat: what the recharge alone does to p and k.
    unheated = out / "sellafield_far_field_unheated.yaml"
    unheated.write_text(scene.read_text().replace("power: 300 W/m", "power: 0 W/m")
                        .replace("name: sellafield_far_field", "name: sellafield_far_field_unheated"))
    run([fissure, "run", unheated, "--output", out / "unheated", "--no-plots"] + quick_far)
    draw_k_stress(study, out / "chain_k_stress.png")
    draw_far_field(out / "far_field" / "results.h5", out / "unheated" / "results.h5",
                   out / "chain_far_field.png")
    print(f"chain: {out}/chain_k_stress.png, {out}/chain_far_field.png")


if __name__ == "__main__":
    main()
