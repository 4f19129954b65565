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

The heat case (`--case heat` or `both`; the default `mandel` runs
Mandel's problem alone, as before): heat_scene.yaml (beside this file), the
square [0, 1 m]^2 at 100 degC with its four sides held at 0 degC, the
thermal process alone (P1 triangles, backward Euler, dt = 1000 s, lumped
capacity, CHOLMOD factor reused), on CGAL meshes of about --heat-sizes
nodes (element size h = sqrt(2.5 / nodes)). Per size Fissure runs once with
results.h5 (the mesh and the last temperatures; 1 + steps steps), then
--heat-repeat rounds (default 3; each figure the median of the rounds, the
step's spread (max - min) / median in results_heat.csv) of: Fissure twice
without results.h5 (1 and 1 + steps steps: summary.json's thermal
`mesh.seconds` is the start-up, meshing and matrices; its `step_seconds`
the steps), and every dolfinx run.
dolfinx_heat.py solves the same problem on Fissure's mesh (read from that
results.h5), its right-hand side assembled from the form each step ("form",
dolfinx's usual loop) or as a product with the capacity matrix ("matvec"),
with each of --heat-dolfinx-solvers, and once on its own create_rectangle
mesh of about the same nodes (the start-up with dolfinx's mesher). Each
dolfinx run on Fissure's mesh reports the largest difference of its nodal
temperatures from Fissure's after the same steps (`fissure_difference`,
relative to the largest temperature); every run the centre temperature
against the closed form (heat_exact.py), in kelvin. plot.py runs with
/usr/bin/python3 (matplotlib).

Usage: run.py BUILD_DIR [--case mandel|heat|both] [--sizes 32,64,128,256,334] [--steps 50]
              [--cpu 0] [--dolfinx-solvers umfpack,mumps] [--install]
              [--heat-sizes 1e4,1e5,1e6] [--heat-steps 50] [--heat-repeat 3]
              [--heat-capacity lumped] [--heat-dolfinx-solvers cholmod]
Writes results.csv (Mandel) and results_heat.csv (heat) here; plot.py draws
fenicsx.png and fenicsx_heat.png.
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile

import heat_exact
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


def fissure_runs(exe, scene_text, steps, cpu, tmp):
    """Fissure's two runs of a scene, of 1 and 1 + steps steps (the later
    steps' mean is the difference of the stepping times over `steps`):
    per run its step count, summary.json and peak memory (kB)."""
    scene = pathlib.Path(tmp) / "scene.yaml"
    scene.write_text(scene_text)
    for count in (1, 1 + steps):
        out = pathlib.Path(tmp) / f"out{count}"
        rss = timed([str(exe), "run", str(scene), "-o", str(out), "--no-plots", "-q",
                     "--max-steps", str(count)], cpu, tmp)
        yield count, json.loads((out / "summary.json").read_text()), rss


def run_fissure(exe, n, steps, cpu):
    with tempfile.TemporaryDirectory() as tmp:
        result = {}
        for count, summary, rss in fissure_runs(exe, fissure_scene(n), steps, cpu, tmp):
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


def heat_scene(nodes, capacity, hdf5):
    """heat_scene.yaml with the element size for about `nodes` mesh nodes
    (2.5 / h^2 on the unit square, docs/thermal.md 2), the capacity and,
    for the timing runs, no results.h5."""
    h = (2.5 / nodes) ** 0.5
    return edited(here / "heat_scene.yaml", [
        ("  mesh: {element_size: 0.05 m}",
         f"  mesh: {{element_size: {h:.9g} m, max_elements: 1e8}}"),
        ("  capacity: lumped", f"  capacity: {capacity}"),
        ("output:\n  interval: 0",
         "output:\n  interval: 0\n  hdf5: " + ("true" if hdf5 else "false")),
    ])


def run_fissure_heat_mesh(exe, nodes, steps, capacity, cpu, tmp):
    """The run with results.h5 (1 + steps steps): dolfinx's mesh, and the
    temperatures to compare with."""
    scene = pathlib.Path(tmp) / "heat_h5.yaml"
    scene.write_text(heat_scene(nodes, capacity, True))
    out = pathlib.Path(tmp) / "mesh"
    timed([str(exe), "run", str(scene), "-o", str(out), "--no-plots", "-q",
           "--max-steps", str(1 + steps)], cpu, tmp)
    summary = json.loads((out / "summary.json").read_text())
    return out / "results.h5", summary["processes"]["thermal"]["mesh"]["nodes"]


def run_fissure_heat(exe, nodes, steps, capacity, cpu, tmp):
    """The two timed runs (fissure_runs) without results.h5."""
    result = {}
    for count, summary, rss in fissure_runs(exe, heat_scene(nodes, capacity, False), steps, cpu,
                                            tmp):
        th = summary["processes"]["thermal"]
        if count == 1:
            result.update(nodes=th["mesh"]["nodes"], startup_s=th["mesh"]["seconds"],
                          first_step_s=th["step_seconds"], solve_1=th["solve_seconds"])
        else:
            result.update(step_s=(th["step_seconds"] - result["first_step_s"]) / steps,
                          solve_s=(th["solve_seconds"] - result["solve_1"]) / steps,
                          peak_mb=rss / 1024, t_end=summary["simulated_time"],
                          T_centre=summary["monitors"]["centre"]["T"], import_s=0.0)
    return result


def run_dolfinx_heat(steps, cpu, tmp, options):
    out = pathlib.Path(tmp) / "dolfinx_heat.json"
    rss = timed([PYTHON, str(here / "dolfinx_heat.py"), str(1 + steps), "--json", str(out)]
                + options, cpu, tmp)
    d = json.loads(out.read_text())
    diff = d["fissure_difference"]
    return {"nodes": d["nodes"], "import_s": d["time_import"], "read_s": d["time_read_mesh"],
            "startup_s": d["time_mesh"] + d["time_setup"], "first_step_s": d["time_first_step"],
            "step_s": d["time_step_mean"], "peak_mb": rss / 1024, "t_end": d["t_end"],
            "T_centre": d["T_centre"], "difference": diff["max_relative_to_max"] if diff else ""}


def heat_error(value, t):
    return value - heat_exact.temperature(0.5, 0.5, t)


def heat_case(exe, args, cpu, have_dolfinx):
    """Per size: Fissure's run with results.h5, then --heat-repeat rounds of
    Fissure's two timed runs and every dolfinx run; each time the median of
    the rounds (the step's spread, (max - min) / median, in its column)."""
    solvers = [s for s in args.heat_dolfinx_solvers.split(",") if s]
    capacity = ["--capacity", args.heat_capacity]
    if have_dolfinx:
        # FFCx compiles the forms on their first use: once here, so that no
        # measured start-up holds the compilation.
        with tempfile.TemporaryDirectory() as tmp:
            for rhs in ("form", "matvec"):
                run_dolfinx_heat(1, None, tmp, ["--mesh", "rectangle", "--nodes", "100",
                                                "--rhs", rhs] + capacity)
    rows = []
    for nodes in (float(s) for s in args.heat_sizes.split(",")):
        with tempfile.TemporaryDirectory() as tmp:
            h5, mesh_nodes = run_fissure_heat_mesh(exe, nodes, args.heat_steps,
                                                   args.heat_capacity, cpu, tmp)
            runs = [("fissure", "fissure", "-", "cholmod", None)]
            if have_dolfinx:
                runs += [("dolfinx", "fissure", rhs, solver, ["--h5", str(h5)])
                         for solver in solvers for rhs in ("form", "matvec")]
                runs.append(("dolfinx", "rectangle", "matvec", solvers[0],
                             ["--mesh", "rectangle", "--nodes", str(mesh_nodes)]))
            samples = {run[:4]: [] for run in runs}
            for _ in range(args.heat_repeat):
                for code, mesh, rhs, solver, where in runs:
                    if code == "fissure":
                        f = run_fissure_heat(exe, nodes, args.heat_steps, args.heat_capacity,
                                             cpu, tmp)
                        if f["nodes"] != mesh_nodes:
                            sys.exit(f"the mesh changed between runs: {f['nodes']} nodes, "
                                     f"{mesh_nodes} with results.h5")
                        samples[(code, mesh, rhs, solver)].append(f)
                        continue
                    try:
                        samples[(code, mesh, rhs, solver)].append(run_dolfinx_heat(
                            args.heat_steps, cpu, tmp,
                            where + capacity + ["--rhs", rhs, "--solver", solver]))
                    except subprocess.CalledProcessError:
                        print(f"{nodes:7.0e} dolfinx  {mesh} {rhs} {solver} failed (see its "
                              "messages above)", flush=True)
            fissure_step = None
            for (code, mesh, rhs, solver), got in samples.items():
                if not got:
                    continue
                m = {key: statistics.median([g[key] for g in got])
                     for key in ("import_s", "startup_s", "first_step_s", "step_s", "peak_mb")}
                steps = [g["step_s"] for g in got]
                spread = (max(steps) - min(steps)) / m["step_s"]
                last = got[-1]
                error = heat_error(last["T_centre"], last["t_end"])
                if code == "fissure":
                    fissure_step = m["step_s"]
                    difference = 0.0
                    extra = ""
                else:
                    difference = last["difference"]
                    extra = (f" (+ import {m['import_s']:.2f} s, reading "
                             f"{statistics.median([g['read_s'] for g in got]):.2f} s)")
                ratio = fissure_step / m["step_s"]
                solve_ms = (statistics.median([g["solve_s"] for g in got]) * 1e3
                            if code == "fissure" else None)
                solve = f"(solve {solve_ms:.3f} ms) " if solve_ms is not None else ""
                row = {"target": f"{nodes:g}", "code": code, "mesh": mesh, "rhs": rhs,
                       "solver": solver, "capacity": args.heat_capacity, "nodes": last["nodes"],
                       "repeats": len(got), **m, "step_spread": spread,
                       "T_centre": last["T_centre"], "error_K": error,
                       "difference_to_fissure": difference, "step_ratio": ratio}
                if code == "fissure":  # its CHOLMOD solves alone, per step
                    row["solve_s"] = statistics.median([g["solve_s"] for g in got])
                rows.append(row)
                print(f"{nodes:7.0e} {code:8s} {last['nodes']:8d} nodes ({mesh} mesh, {rhs}, "
                      f"{solver}): start-up {m['startup_s']:7.2f} s{extra}, first step "
                      f"{m['first_step_s']:8.4f} s, step {m['step_s'] * 1e3:8.3f} ms "
                      f"{solve}(spread {spread:.2f} over {len(got)}), peak "
                      f"{m['peak_mb']:7.0f} MB, T centre {last['T_centre']:.9f} (error "
                      f"{error:+.3e} K), difference to Fissure "
                      f"{difference if difference != '' else '-'}; Fissure / this: step "
                      f"{ratio:.2f}", flush=True)
    write_rows(args.heat_output, rows)


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
    parser.add_argument("--case", choices=["mandel", "heat", "both"], default="mandel",
                        help="Mandel's problem (default), the heat case, or both")
    parser.add_argument("--heat-sizes", default="1e4,1e5,1e6",
                        help="the heat case's meshes: about this many nodes each")
    parser.add_argument("--heat-steps", type=int, default=50)
    parser.add_argument("--heat-repeat", type=int, default=3,
                        help="rounds of the heat case's timed runs (their median is reported)")
    parser.add_argument("--heat-capacity", choices=["lumped", "consistent"], default="lumped")
    parser.add_argument("--heat-dolfinx-solvers", default="cholmod",
                        help="of dolfinx_heat.py's: cholmod, mumps, petsc")
    parser.add_argument("--heat-output", type=pathlib.Path, default=here / "results_heat.csv")
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
    if args.case in ("heat", "both"):
        heat_case(exe, args, cpu, have_dolfinx)
    if args.case == "heat":
        return
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
