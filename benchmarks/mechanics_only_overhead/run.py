#!/usr/bin/env python3
"""Benchmark: a mechanics-only scene with the thermal code built but not
switched on, against the same scene before the thermal code existed
(issue 23, "Skip what is not needed": within 2 % of its previous time).

Builds `fissure` at a baseline revision (default caca69f, the last commit of
main before the thermal strain, the THM coordinator and the thermal process
were merged) in BUILD_DIR/baseline-REV (a git worktree, Release, kept for the
next run), then runs each mechanics-only scene with both executables in
alternation (REPEATS times each, --no-plots, one process at a time) and
compares the mechanics' time per step from summary.json (the sum of the
DDA's own timers, processes.mechanics.seconds, over the steps: without
start-up and output; both revisions report them). Both must produce the same results:
the scenes' monitors are compared to the bit, so that the ratio compares the
same work. Writes results.csv here and prints the median ratios.

Usage: run.py BUILD_DIR [--baseline REV] [--repeats N] [--steps N]
"""
import argparse
import csv
import json
import os
import pathlib
import shutil
import statistics
import subprocess
import sys

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
# (scene, steps): the DDA benchmark scene and a jointed rock mass.
SCENES = [("configs/brick_wall_1000.yaml", 60), ("configs/jointed_slope.yaml", 60)]


def build_baseline(build_dir, rev):
    tree = build_dir / f"baseline-{rev}"
    exe = tree / "build" / "app" / "fissure"
    if exe.exists():
        return exe
    if not tree.exists():
        subprocess.check_call(["git", "-C", str(root), "worktree", "add", "--detach", str(tree), rev])
    subprocess.check_call(["cmake", "-S", str(tree), "-B", str(tree / "build"),
                           "-DCMAKE_BUILD_TYPE=Release", "-DFISSURE_BUILD_TESTS=OFF",
                           "-DFISSURE_BUILD_BENCHMARKS=OFF"], stdout=subprocess.DEVNULL)
    subprocess.check_call(["cmake", "--build", str(tree / "build"), "--target", "fissure", "-j",
                           str(os.cpu_count() or 2)])
    return exe


def run(exe, scene, steps, out):
    if out.exists():
        shutil.rmtree(out)
    subprocess.check_call([str(exe), "run", str(root / scene), "-o", str(out), "--max-steps",
                           str(steps), "-q", "--no-plots"], stdout=subprocess.DEVNULL)
    s = json.loads((out / "summary.json").read_text())
    seconds = sum(s["processes"]["mechanics"]["seconds"].values())
    return seconds / s["steps"], (out / "monitors.csv").read_text()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build_dir")
    ap.add_argument("--baseline", default="caca69f")
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--csv", default=str(here / "results.csv"))
    a = ap.parse_args()
    build_dir = pathlib.Path(a.build_dir).resolve()
    current = build_dir / "app" / "fissure"
    baseline = build_baseline(build_dir, a.baseline)
    out = build_dir / "bench-output" / "mechanics_only_overhead"
    rows, worst = [], 0.0
    for scene, steps in SCENES:
        times = {"baseline": [], "current": []}
        monitors = {}
        for _ in range(a.repeats):
            for name, exe in (("baseline", baseline), ("current", current)):
                t, m = run(exe, scene, steps, out / name)
                times[name].append(t)
                monitors[name] = m
        same = monitors["baseline"] == monitors["current"]
        b, c = statistics.median(times["baseline"]), statistics.median(times["current"])
        ratio = c / b
        worst = max(worst, ratio)
        rows.append({"scene": scene, "steps": steps, "repeats": a.repeats,
                     "baseline_ms_per_step": f"{1e3 * b:.3f}",
                     "current_ms_per_step": f"{1e3 * c:.3f}", "ratio": f"{ratio:.4f}",
                     "same_results": same})
        print(f"{scene}: {steps} steps x {a.repeats}: baseline {a.baseline} {1e3 * b:.2f} ms/step, "
              f"current {1e3 * c:.2f} ms/step, ratio {ratio:.4f}"
              f"{'' if same else '  (monitors differ: not the same work)'}")
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"worst ratio {worst:.4f} (target <= 1.02)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
