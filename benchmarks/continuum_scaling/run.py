#!/usr/bin/env python3
"""Benchmark: the continuum's wall time per step against its unknowns, on one
and two MPI ranks, with the direct solvers and with PETSc's Krylov solvers
(issue 24: 1e6 unknowns u-p-T in at most 10 s per step on 2 ranks, the
linear iterations per step nearly independent of the mesh size, the
speed-up from 1 to 2 ranks).

The scene is configs/continuum_mandel.yaml with heat (its right side held at
50 degC, thermal expansion 1e-5 1/K), on N x N cells of Taylor-Hood
triangles: about 10 N^2 unknowns u-p-T. Monolithic scheme (one u-p solve
and one heat solve a step; fixed stress takes 16 passes a step at Mandel's
coupling strength). Each case runs 1 and then 1 + STEPS steps; the time per
step is the difference of processes.continuum.seconds.steps over STEPS: the
first step's factorization or preconditioner set-up is left out and
reported separately ("first step"). Writes results.csv here; plot.py draws
scaling.png.

Usage: run.py BUILD_DIR [--sizes 32,100,316] [--steps 3] [--quick] [--solvers direct,mumps,petsc]
              [--krylov-one-rank-max N]
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
sys.path.insert(0, str(here.parent))
from common.results_csv import write_rows  # noqa: E402
from common.scene_edits import edited  # noqa: E402
# (ranks, solver): `direct` on 2 ranks factorizes on rank 0 (reproducible to
# the bit); `mumps` is PETSc's MUMPS, which shares the factor among the
# ranks but is not (docs/continuum.md 3).
CASES = [(1, "direct"), (2, "direct"), (2, "mumps"), (1, "petsc"), (2, "petsc")]
SOLVERS = {
    "direct": "{type: direct}",
    "mumps": '{type: petsc, petsc_options: "-ksp_type preonly -pc_type lu '
             '-pc_factor_mat_solver_type mumps"}',
    "petsc": "{type: petsc}",
}


def scene_text(n):
    return edited(root / "configs" / "continuum_mandel.yaml", [
        ("  mesh: {divisions: [16, 16]}", f"  mesh: {{divisions: [{n}, {n}], max_elements: 1e7}}"),
        ("  time_step: 0.01 s", "  time_step: 0.01 s\n  scheme: monolithic\n  solver: SOLVER"),
        ("    - {boundary: right, pressure: 0}",
         "    - {boundary: right, pressure: 0}\n    - {boundary: right, temperature: 50}"),
        ("permeability: 1e-13 m^2}", "permeability: 1e-13 m^2, thermal_expansion: 1e-5 1/K}"),
        ("output:\n  interval: 0.7 s", "output:\n  interval: 100 s\n  hdf5: false"),
    ])


def run(exe, scene, ranks, steps, out):
    command = [str(exe), "run", str(scene), "-o", str(out), "--no-plots", "-q",
               "--max-steps", str(steps)]
    env = dict(os.environ)
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "--oversubscribe"] + command
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return json.loads((out / "summary.json").read_text())["processes"]["continuum"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--sizes", default="32,100,316")
    parser.add_argument("--steps", type=int, default=3)
    parser.add_argument("--quick", action="store_true", help="sizes 16,32 (a check of the script)")
    parser.add_argument("--solvers", default="direct,mumps,petsc", help="the solvers to run")
    parser.add_argument("--krylov-one-rank-max", type=int, default=100,
                        help="largest N of the Krylov solver on one rank (at 316 it takes minutes)")
    args = parser.parse_args()
    exe = args.build_dir.resolve() / "app" / "fissure"
    sizes = [16, 32] if args.quick else [int(s) for s in args.sizes.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for n in sizes:
            for ranks, solver in CASES:
                if solver not in args.solvers.split(","):
                    continue
                if solver == "petsc" and ranks == 1 and n > args.krylov_one_rank_max:
                    continue
                scene = tmp / f"scaling_{n}_{solver}.yaml"
                scene.write_text(scene_text(n).replace("SOLVER", SOLVERS[solver]))
                one = run(exe, scene, ranks, 1, tmp / "one")
                more = run(exe, scene, ranks, 1 + args.steps, tmp / "more")
                per_step = (more["seconds"]["steps"] - one["seconds"]["steps"]) / args.steps
                its = (more["linear_iterations"] - one["linear_iterations"]) / args.steps
                row = {"cells": n, "unknowns": more["mesh"]["unknowns"], "ranks": ranks,
                       "solver": more["linear_solver"], "start_s": round(more["seconds"]["assembly"], 3),
                       "first_step_s": round(one["seconds"]["steps"], 3),
                       "per_step_s": round(per_step, 4), "iterations_per_step": round(its, 1)}
                rows.append(row)
                print(f"{n:4d} x {n:<4d} {row['unknowns']:>9d} unknowns, {ranks} rank(s), "
                      f"{row['solver']}: start {row['start_s']} s, first step {row['first_step_s']} s, "
                      f"{row['per_step_s']} s per step, {row['iterations_per_step']} iterations per step",
                      flush=True)
    write_rows(here / "results.csv", rows)


if __name__ == "__main__":
    main()
