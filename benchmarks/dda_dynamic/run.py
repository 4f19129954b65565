#!/usr/bin/env python3
"""Benchmark: the cost of dynamic DDA (issue 40, item 5), on one core.

Cases (each a `fissure run` of a scene made from a configs/ file):
  * masada_400: configs/masada_cliff.yaml with the bedding at 1.25 m instead
    of 1.5 m: 418 blocks (417 free) of jointed dolomite on a rigid base
    shaken by the 0.6 g record from t = 1 s, dt 1 ms, 25,000 steps (target:
    at most 60 s on one core);
  * wall_1000_dynamic: configs/brick_wall_1000.yaml (1,010 bricks) dynamic
    (k01 = 1) from rest, steps 1-40, g2 w = 2 cm as in dda_scaling (target:
    at most 15 ms per step);
  * wall_1000_static: the same wall static (k01 = 0), whole settle, steps
    1-300 (target: at most 5 ms per step);
  * wall_106_dynamic: configs/brick_wall.yaml (106 bricks, dynamic), 1,000
    steps.
Reported per case: the CPU time of the child process (user + system; a
run's start-up, reading the scene and writing output included), the
mechanics' own seconds (its stopwatches: detection, assembly, solve,
open-close, update; wall time of one thread pinned to one core), both per
accepted step; steps, open-close iterations per step, cuts, factorizations.
`--baseline EXE` runs every case with a second fissure executable too and
prints the ratios (paired runs, the two alternate). Writes results.csv here.

Usage: run.py BUILD_DIR [--baseline EXE] [--cases masada_400,...] [--repeat 1]
              [--masada-steps 25000] [--cpu 0]
"""
import argparse
import json
import os
import pathlib
import resource
import subprocess
import sys
import tempfile

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
sys.path.insert(0, str(here.parent))
from common.results_csv import write_rows  # noqa: E402
from common.scene_edits import edited  # noqa: E402


def masada_400():
    source = root / "configs" / "masada_cliff.yaml"
    return edited(source, [
        ("dip: 4, spacing: 1.5 m", "dip: 4, spacing: 1.25 m"),
        ("file: records/", f"file: {root / 'configs' / 'records'}/"),
        ("  end: 21 s", "  end: 60 s"),
        ("  interval: 0.05", "  interval: 1\n  hdf5: false"),
    ])


def wall_1000(k01):
    source = root / "configs" / "brick_wall_1000.yaml"
    # g2 such that g2 w = 2 cm, w = 26 m (benchmarks/dda_scaling).
    return edited(source, [
        ("    velocity_carry_over: 0.0",
         f"    velocity_carry_over: {k01}\n    max_displacement_ratio: {0.02 / 26:.6g}"),
        ("  checkpoint_steps: 200", "  hdf5: false"),
        ("  interval: 0.01", "  interval: 100"),
    ])


def wall_106():
    source = root / "configs" / "brick_wall.yaml"
    return edited(source, [
        ("  end: 1.0", "  end: 100"),
        ("  interval: 0.02", "  interval: 100\n  hdf5: false"),
    ])


# name: (scene text, accepted steps to run, target ms per step or None)
CASES = {
    "masada_400": (masada_400, 25000, 60e3 / 25000),
    "wall_1000_dynamic": (lambda: wall_1000(1.0), 40, 15.0),
    "wall_1000_static": (lambda: wall_1000(0.0), 300, 5.0),
    "wall_106_dynamic": (wall_106, 1000, None),
}


def run(exe, text, steps, cpu):
    with tempfile.TemporaryDirectory() as tmp:
        scene = pathlib.Path(tmp) / "scene.yaml"
        scene.write_text(text)
        out = pathlib.Path(tmp) / "out"
        command = [str(exe), "run", str(scene), "-o", str(out), "--no-plots", "-q",
                   "--max-steps", str(steps)]
        if cpu is not None:
            command = ["taskset", "-c", str(cpu)] + command
        env = dict(os.environ, OMP_NUM_THREADS="1")
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu_seconds = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        mech = json.loads((out / "summary.json").read_text())["processes"]["mechanics"]
    steps_done = mech["steps"]
    s = mech["seconds"]
    solver = mech["linear_solver"]
    factorizations = solver.get("reused_factorization", {}).get("factorizations", 0)
    direct = solver.get("direct", {})
    factorizations += direct.get("cholesky_factorizations", 0) + direct.get("lu_factorizations", 0)
    cuts = sum(mech["time_step_cuts"].values())
    own = sum(s.values())
    return {
        "blocks": mech["blocks"]["total"],
        "steps": steps_done,
        "cpu_s": cpu_seconds,
        "cpu_ms_per_step": 1e3 * cpu_seconds / steps_done,
        "mechanics_ms_per_step": 1e3 * own / steps_done,
        "detection_ms": 1e3 * s["contact_detection"] / steps_done,
        "assembly_ms": 1e3 * s["assembly"] / steps_done,
        "solve_ms": 1e3 * s["solve"] / steps_done,
        "open_close_ms": 1e3 * s["open_close"] / steps_done,
        "update_ms": 1e3 * s["update"] / steps_done,
        "iterations_per_step": mech["open_close_iterations"] / steps_done,
        "cuts": cuts,
        "factorizations_per_step": factorizations / steps_done,
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--baseline", type=pathlib.Path, help="a second fissure executable")
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--masada-steps", type=int, default=25000)
    parser.add_argument("--cpu", type=int, default=0, help="core to pin to (-1: none)")
    parser.add_argument("--output", type=pathlib.Path, default=here / "results.csv")
    args = parser.parse_args()
    exes = [("current", args.build_dir / "app" / "fissure")]
    if args.baseline:
        exes.append(("baseline", args.baseline))
    cpu = None if args.cpu < 0 else args.cpu
    rows = []
    for name in args.cases.split(","):
        make, steps, target = CASES[name]
        if name == "masada_400":
            steps = args.masada_steps
        text = make()
        for r in range(args.repeat):
            for label, exe in exes:
                row = {"case": name, "binary": label, "repeat": r, "target_ms": target}
                row.update(run(exe, text, steps, cpu))
                rows.append(row)
                print(f"{name:18s} {label:8s} {row['blocks']:5d} blocks {row['steps']:6d} steps: "
                      f"CPU {row['cpu_s']:8.2f} s = {row['cpu_ms_per_step']:7.3f} ms/step "
                      f"(mechanics {row['mechanics_ms_per_step']:7.3f}: detection "
                      f"{row['detection_ms']:.3f}, assembly {row['assembly_ms']:.3f}, solve "
                      f"{row['solve_ms']:.3f}), its/step {row['iterations_per_step']:.2f}, "
                      f"cuts {row['cuts']}, factorizations/step "
                      f"{row['factorizations_per_step']:.2f}", flush=True)
        if args.baseline:
            mine = [x["cpu_s"] for x in rows if x["case"] == name and x["binary"] == "current"]
            theirs = [x["cpu_s"] for x in rows if x["case"] == name and x["binary"] == "baseline"]
            print(f"{name:18s} current / baseline CPU: "
                  + ", ".join(f"{a / b:.3f}" for a, b in zip(mine, theirs)))
    write_rows(args.output, rows)


if __name__ == "__main__":
    main()
