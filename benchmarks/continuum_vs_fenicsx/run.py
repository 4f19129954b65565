#!/usr/bin/env python3
"""Benchmark: the continuum side by side with FEniCSx (dolfinx) on the same
work (issue 41).

Mandel's problem as configs/continuum_mandel.yaml sets it, monolithic u-p
(Taylor-Hood P2/P1, backward Euler, dt = 0.01 s), on N x N cells of the same
chessboard mesh, the same reduced system (the rigid plate's u_y one unknown)
and the same direct solver (UMFPACK; dolfinx also with MUMPS), one core
(taskset, one thread for OpenMP and OpenBLAS). Fissure is run with
`fissure run`; dolfinx with dolfinx_mandel.py (beside this file), which
builds the same system with dolfinx and petsc4py.

Per case and code: the unknowns, the start-up (Fissure: meshing and
assembly, the undrained start included; dolfinx: import, mesh, forms,
assembly, reduction and the undrained start), the first step (its
factorization), the mean of the later steps, the peak resident memory of
the process (/usr/bin/time), and the pressure at the centre after the
steps against the closed form (mandel_exact.py), in units of p0.

dolfinx is Debian's python3-dolfinx; when `import dolfinx` fails the
benchmark says so and runs Fissure alone (`--install` runs apt-get install
python3-dolfinx first).

Usage: run.py BUILD_DIR [--sizes 32,64,128,256,334] [--steps 50] [--cpu 0]
              [--dolfinx-solvers umfpack,mumps] [--install]
Writes results.csv here; plot.py draws fenicsx.png.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile

import mandel_exact

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
sys.path.insert(0, str(here.parent))
from common.results_csv import write_rows  # noqa: E402
from common.scene_edits import edited  # noqa: E402
PYTHON = "/usr/bin/python3"  # Debian's, where python3-dolfinx installs


def fissure_scene(n):
    return edited(root / "configs" / "continuum_mandel.yaml", [
        ("  mesh: {divisions: [16, 16]}", f"  mesh: {{divisions: [{n}, {n}], max_elements: 1e7}}"),
        ("  time_step: 0.01 s",
         "  time_step: 0.01 s\n  scheme: monolithic\n  solver: {type: direct}"),
        ("output:\n  interval: 0.7 s", "output:\n  interval: 100 s\n  hdf5: false"),
    ])


def timed(command, cpu, tmp):
    """Runs command pinned to `cpu`; returns its peak resident memory (kB)."""
    memory = pathlib.Path(tmp) / "maxrss"
    full = ["/usr/bin/time", "-f", "%M", "-o", str(memory)]
    if cpu is not None:
        full += ["taskset", "-c", str(cpu)]
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    subprocess.run(full + command, env=env, check=True, stdout=subprocess.DEVNULL)
    return int(memory.read_text().split()[-1])


def run_fissure(exe, n, steps, cpu):
    """Two runs, of 1 and 1 + steps steps: the later steps' mean is the
    difference of the stepping times over `steps`."""
    with tempfile.TemporaryDirectory() as tmp:
        scene = pathlib.Path(tmp) / "mandel.yaml"
        scene.write_text(fissure_scene(n))
        result = {}
        for count in (1, 1 + steps):
            out = pathlib.Path(tmp) / f"out{count}"
            rss = timed([str(exe), "run", str(scene), "-o", str(out), "--no-plots", "-q",
                         "--max-steps", str(count)], cpu, tmp)
            summary = json.loads((out / "summary.json").read_text())
            c = summary["processes"]["continuum"]
            s = c["seconds"]
            if count == 1:
                result.update(unknowns=c["mesh"]["unknowns"], startup_s=s["mesh"] + s["assembly"],
                              first_step_s=s["steps"], factor_entries=c["factors"]
                              .get("monolithic", {}).get("entries", 0))
                first = s["steps"]
            else:
                result.update(step_s=(s["steps"] - first) / steps, peak_mb=rss / 1024,
                              time=summary["simulated_time"],
                              p_centre=summary["monitors"]["centre"]["p"])
    return result


def factor_entries(size):
    """MUMPS's INFOG(29) (entries of the factors; negative: millions);
    0 where the package does not tell (UMFPACK through PETSc)."""
    if not size:
        return 0
    entries = size.get("infog29", 0)
    return -entries * 1e6 if entries < 0 else entries


def run_dolfinx(n, steps, solver, cpu):
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "dolfinx.json"
        # 1 + steps steps, as Fissure's longer run: the first, then `steps`
        # whose mean is the step time.
        rss = timed([PYTHON, str(here / "dolfinx_mandel.py"), str(n), str(1 + steps), "--solver",
                     solver, "--json", str(out)], cpu, tmp)
        d = json.loads(out.read_text())
    return d, rss


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--sizes", default="32,64,128,256,334")
    parser.add_argument("--steps", type=int, default=50)
    parser.add_argument("--cpu", type=int, default=0, help="core to pin to (-1: none)")
    parser.add_argument("--dolfinx-solvers", default="umfpack,mumps")
    parser.add_argument("--install", action="store_true",
                        help="apt-get install python3-dolfinx when it is missing")
    parser.add_argument("--output", type=pathlib.Path, default=here / "results.csv")
    args = parser.parse_args()
    cpu = None if args.cpu < 0 else args.cpu
    have_dolfinx = subprocess.run([PYTHON, "-c", "import dolfinx"],
                                  capture_output=True).returncode == 0
    if not have_dolfinx and args.install:
        subprocess.run(["apt-get", "install", "-y", "-q", "python3-dolfinx"], check=False,
                       env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
        have_dolfinx = subprocess.run([PYTHON, "-c", "import dolfinx"],
                                      capture_output=True).returncode == 0
    if not have_dolfinx:
        print("dolfinx is not installed (Debian: apt-get install python3-dolfinx, or --install): "
              "Fissure alone, no ratios", flush=True)
    exe = args.build_dir / "app" / "fissure"
    rows = []
    for n in (int(s) for s in args.sizes.split(",")):
        f = run_fissure(exe, n, args.steps, cpu)
        exact = mandel_exact.pressure(0, f["time"])
        error = abs(f["p_centre"] - exact) / mandel_exact.P0
        row = {"n": n, "code": "fissure", "solver": "umfpack", "unknowns": f["unknowns"],
               "startup_s": f["startup_s"], "first_step_s": f["first_step_s"],
               "step_s": f["step_s"], "peak_mb": f["peak_mb"], "factor_entries":
               f["factor_entries"], "p_error": error, "step_ratio": 1.0}
        rows.append(row)
        print(f"N = {n:4d} fissure  umfpack {f['unknowns']:8d} unknowns: start-up "
              f"{f['startup_s']:7.2f} s, first step {f['first_step_s']:7.3f} s, step "
              f"{f['step_s']:7.4f} s, peak {f['peak_mb']:7.0f} MB, error {error:.2e} p0",
              flush=True)
        if not have_dolfinx:
            continue
        for solver in filter(None, args.dolfinx_solvers.split(",")):
            try:
                d, rss = run_dolfinx(n, args.steps, solver, cpu)
            except subprocess.CalledProcessError:
                # PETSc's UMFPACK (32-bit) fails at 1e6 unknowns: "umfpack_UMF_numeric failed".
                print(f"N = {n:4d} dolfinx  {solver:7s} failed (see its messages above)",
                      flush=True)
                continue
            error = abs(d["p_centre"] - mandel_exact.pressure(0, d["t_end"])) / mandel_exact.P0
            startup = d["time_import"] + d["time_mesh"] + d["time_setup"] + d["time_undrained"]
            d["step_s"], d["first_step_s"] = d["time_step_mean"], d["time_first_step"]
            d["unknowns"] = d["unknowns_reduced"]
            r = {"n": n, "code": "dolfinx", "solver": solver, "unknowns": d["unknowns"],
                 "startup_s": startup, "first_step_s": d["first_step_s"], "step_s": d["step_s"],
                 "peak_mb": rss / 1024, "factor_entries": factor_entries(d["factor_steps"]),
                 "p_error": error, "step_ratio": f["step_s"] / d["step_s"]}
            rows.append(r)
            print(f"N = {n:4d} dolfinx  {solver:7s} {d['unknowns']:8d} unknowns: start-up "
                  f"{startup:7.2f} s, first step {d['first_step_s']:7.3f} s, step "
                  f"{d['step_s']:7.4f} s, peak {r['peak_mb']:7.0f} MB, error {error:.2e} p0; "
                  f"Fissure / dolfinx: step {f['step_s'] / d['step_s']:.2f}, first step "
                  f"{f['first_step_s'] / d['first_step_s']:.2f}, start-up "
                  f"{f['startup_s'] / startup:.2f}, memory {f['peak_mb'] / r['peak_mb']:.2f}",
                  flush=True)
    write_rows(args.output, rows)


if __name__ == "__main__":
    main()
