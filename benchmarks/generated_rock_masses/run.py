#!/usr/bin/env python3
"""Benchmark: hundreds of generated rock masses settling under gravity
(issue 22, item 1; docs/performance.md "Generated rock masses").

Runs tests/robustness/generated_rock_masses.py over seeds 1 ... N (N/19 of
each generator: joint sets in a box and in a slope, every DFN orientation and
length law, excavations, DFN slopes), 30 ms from rest at 1 ms steps, and
writes results.csv here (one row per rock mass: status, steps, step cuts,
open-close iterations, held contacts, blocks, wall time). plot.py turns it
into generated_rock_masses.png and the table of docs/performance.md.

Usage: run.py BUILD_DIR [--cases N] [--fissure BIN] [--csv FILE]
  (BUILD_DIR/app/fissure unless --fissure; `benchmarks/run_all.sh` passes BUILD_DIR)
"""
import argparse
import pathlib
import subprocess
import sys

here = pathlib.Path(__file__).resolve().parent
driver = here.parent.parent / "tests" / "robustness" / "generated_rock_masses.py"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build_dir")
    ap.add_argument("--cases", type=int, default=304)
    ap.add_argument("--fissure")
    ap.add_argument("--csv", default=str(here / "results.csv"))
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    fissure = a.fissure or str(pathlib.Path(a.build_dir) / "app" / "fissure")
    out = pathlib.Path(a.build_dir) / "bench-output" / "generated_rock_masses"
    return subprocess.call([sys.executable, str(driver), "--fissure", fissure, "--out", str(out),
                            "--first-seed", "1", "--cases", str(a.cases), "--settle", "0.03",
                            "--max-steps", "1000", "--timeout", "600", "--jobs", str(a.jobs),
                            "--csv", a.csv, "--quiet"])


if __name__ == "__main__":
    sys.exit(main())
