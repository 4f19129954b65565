#!/usr/bin/env python3
"""Checks that every REV study result committed in configs/ is what its study gives.

A scene in configs/ may take its permeability from a `fissure rev` study
(`continuum.materials[].permeability: {rev: <stem>/rev.json}`, docs/continuum.md
section 3, or `{stress_study: <stem>/stress.json}`, section 9). So that the
scene runs without the study having run first, the study's rev.json or
stress.json is committed next to it: configs/<stem>/rev.json (stress.json) is
the output of `fissure rev configs/<stem>.yaml` (the full study, not its CI
line). This script runs each such study in full (into OUTPUT_DIR/<stem>,
--no-plots) and compares the fresh file with the committed one, with the tolerance
rules of the study's CI reference (`<stem>_0` in references/tolerances.json:
the spread measured across builds and BLAS kernels; timings left out). A
committed rev.json without its study fails too.

Regenerate a fixture after an intended change of the study's results:
  build/app/fissure rev configs/<stem>.yaml -o /tmp/<stem> --no-plots
  cp /tmp/<stem>/rev.json configs/<stem>/rev.json   (or stress.json)

Usage: check_rev_fixtures.py FISSURE_EXECUTABLE SOURCE_DIR OUTPUT_DIR
"""
import json
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_with_reference as cwr  # noqa: E402


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    app = str(pathlib.Path(sys.argv[1]).resolve())
    source, output = pathlib.Path(sys.argv[2]).resolve(), pathlib.Path(sys.argv[3]).resolve()
    fixtures = sorted(list((source / "configs").glob("*/rev.json")) +
                      list((source / "configs").glob("*/stress.json")))
    tolerances = cwr.Tolerances(cwr.DEFAULT_REFERENCES / cwr.TOLERANCES)
    failures = []
    for fixture in fixtures:
        stem = fixture.parent.name
        study = source / "configs" / f"{stem}.yaml"
        if not study.is_file():
            failures.append(f"{fixture}: no study configs/{stem}.yaml produces it")
            continue
        folder = output / stem
        shutil.rmtree(folder, ignore_errors=True)
        run = subprocess.run([app, "rev", str(study), "-o", str(folder), "--no-plots"], cwd=source,
                             capture_output=True, text=True)
        if run.returncode != 0:
            failures.append(f"{study}: fissure rev exited {run.returncode}\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
            continue
        name = fixture.name
        reference = {name: ("json", None, cwr.flatten(json.loads(fixture.read_text())))}
        actual = {name: ("json", None, cwr.flatten(json.loads((folder / name).read_text())))}
        mismatches = cwr.compare_results(f"{stem}_0", reference, actual, tolerances)
        print(f"{fixture.relative_to(source)}: "
              + ("matches `fissure rev`" if not mismatches else "DIFFERS from `fissure rev`"))
        failures += [f"{fixture}: {m}" for m in mismatches]
    if not fixtures:
        print("no configs/*/rev.json or stress.json: nothing to check")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
