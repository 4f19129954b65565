#!/usr/bin/env python3
"""Compares the output folder of a config's CI line with its stored reference.

The references (tests/configs/references/<config stem>_<k>/; tests/configs/README.md)
were made with the build of main before a change; `make test` compares every
CI run with them (run_config_ci_lines.py calls compare() after each run), so
that a change not meant to change results is checked. What is compared:

* `monitors.csv` (fissure run): the same rows (by position, the time `t`
  within its tolerance) and the same columns by name; a missing or an extra
  column fails;
* `summary.json` (fissure run, fissure mesh): `status` exactly, and every
  number, boolean and null, flattened to dotted keys
  (`processes.mechanics.open_close_iterations`, `monitors.top.ux`); stored as
  `summary.json` = {"status": ..., "values": {key: value}} in the reference;
* `fissure rev`: `rev.json` flattened the same way (list items by index,
  `sizes.3.k_max.cv`), and `sizes.csv`, `fits.csv`, `domains.csv` like
  monitors.csv; under stress (docs/upscaling.md) `stress.json`,
  `stress_states.csv` and `stress_domains.csv` the same way.

Every value must be within atol + rtol * |reference| of the reference, with
atol and rtol from the first matching rule of tolerances.json; a rule can
also leave a key out (`"ignore": true`: timings, timing-driven solver
choices). A key of the reference that the run does not write fails, unless
it is ignored or tolerances.json's `renamed` maps it to the key that holds
it now (a statistic that moved, with its value still checked); a key that
only the run writes is new information, not a changed result, and passes.
NaN (null in JSON) matches only NaN; booleans match exactly.

Usage:
  compare_with_reference.py OUTPUT_DIR NAME                # compare, exit 1 on a mismatch
  compare_with_reference.py OUTPUT_DIR NAME --update       # store OUTPUT_DIR as NAME's reference
  options: --references DIR (default: references/ next to this script)

NAME is `<config stem>_<k>` (the k-th CI line of configs/<stem>.yaml), as
run_config_ci_lines.py names its output folders. To regenerate every
reference after an intended change of results, run
`run_config_ci_lines.py FISSURE SOURCE_DIR OUTPUT_DIR --update`.
Python 3 standard library only.
"""
import argparse
import csv
import fnmatch
import json
import math
import pathlib
import shutil
import sys

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT_REFERENCES = HERE / "references"
TOLERANCES = "tolerances.json"

# Files of an output folder that hold results, and how they are stored.
CSV_FILES = ("monitors.csv", "sizes.csv", "fits.csv", "domains.csv", "stress_states.csv",
             "stress_domains.csv")
JSON_FILES = ("summary.json", "rev.json", "stress.json")


# ---------------------------------------------------------------- reading


def read_csv(path):
    """(columns, rows) of a CSV file of numbers; rows are lists of floats."""
    with open(path, newline="") as f:
        lines = list(csv.reader(f))
    if not lines:
        raise ValueError(f"{path}: empty")
    columns = [c.strip() for c in lines[0]]
    rows = []
    for n, line in enumerate(lines[1:], start=2):
        if not line:
            continue
        if len(line) != len(columns):
            raise ValueError(f"{path}: line {n} has {len(line)} fields, the header {len(columns)}")
        rows.append([float(v) if v != "" else math.nan for v in line])  # empty: missing
    return columns, rows


def flatten(value, prefix=""):
    """{dotted key: number | bool | None} of a JSON value; strings are left out."""
    out = {}
    if isinstance(value, dict):
        for k, v in value.items():
            out.update(flatten(v, f"{prefix}.{k}" if prefix else str(k)))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            out.update(flatten(v, f"{prefix}.{i}" if prefix else str(i)))
    elif value is None or isinstance(value, (bool, int, float)):
        out[prefix] = value
    return out


def read_results(folder, stored=False):
    """The results of an output folder: {file: ("csv", columns, rows) | ("json",
    status, values)}; `stored`: a reference folder, whose JSON files hold the
    values already flattened."""
    folder = pathlib.Path(folder)
    results = {}
    for name in CSV_FILES:
        if (folder / name).is_file():
            columns, rows = read_csv(folder / name)
            results[name] = ("csv", columns, rows)
    for name in JSON_FILES:
        if (folder / name).is_file():
            data = json.loads((folder / name).read_text())
            results[name] = ("json", data.get("status"), data["values"] if stored else flatten(data))
    return results


def read_output(folder):
    return read_results(folder)


def read_reference(folder):
    return read_results(folder, stored=True)


# ---------------------------------------------------------------- tolerances


class Tolerances:
    """The rules of tolerances.json: the first rule whose config, file and key
    patterns (fnmatch; `*` also matches dots) match applies."""

    def __init__(self, path):
        data = json.loads(pathlib.Path(path).read_text())
        self.rules = data["rules"]
        # reference key -> the key of the run that holds it now
        self.renamed = {k: v["to"] for k, v in data.get("renamed", {}).items()}
        for r in self.rules:
            if not r.get("ignore") and ("atol" not in r or "rtol" not in r):
                raise ValueError(f"{path}: rule without atol/rtol: {r}")

    def rule(self, config, file, key):
        for r in self.rules:
            if (fnmatch.fnmatchcase(config, r.get("config", "*"))
                    and fnmatch.fnmatchcase(file, r.get("file", "*"))
                    and fnmatch.fnmatchcase(key, r.get("key", "*"))):
                return r
        raise KeyError(f"no tolerance rule matches {config} {file} {key}")

    def ignored(self, config, file, key):
        return bool(self.rule(config, file, key).get("ignore"))


# ---------------------------------------------------------------- comparing


def _fmt(v):
    return repr(v) if not isinstance(v, float) else f"{v:.17g}"


def compare_value(ref, act, atol, rtol):
    """(ok, difference, tolerance) for two numbers, booleans or None (NaN)."""
    ref_nan = ref is None or (isinstance(ref, float) and math.isnan(ref))
    act_nan = act is None or (isinstance(act, float) and math.isnan(act))
    if ref_nan or act_nan:
        return ref_nan and act_nan, float("nan"), 0.0
    if isinstance(ref, bool) or isinstance(act, bool):
        return ref is act, float("nan"), 0.0
    if math.isinf(ref) or math.isinf(act):
        return ref == act, float("nan"), 0.0
    tol = atol + rtol * abs(ref)
    diff = abs(act - ref)
    return diff <= tol, diff, tol


def pairs(config, reference, actual, tolerances):
    """The comparisons of a run with its reference: yields
    ("value", file, key, where, reference value, actual value, rule) for every
    compared value and ("structure", message) for a missing or extra file,
    column, row or key, or a different status."""
    for file in sorted(set(reference) | set(actual)):
        if file not in actual:
            yield ("structure", f"{config}: {file}: in the reference, not written by the run")
            continue
        if file not in reference:
            yield ("structure", f"{config}: {file}: written by the run, not in the reference")
            continue
        if reference[file][0] == "csv":
            _, rcols, rrows = reference[file]
            _, acols, arows = actual[file]
            if len(set(rcols)) != len(rcols) or len(set(acols)) != len(acols):
                yield ("structure", f"{config}: {file}: repeated column names")
                continue
            rkeep = [c for c in rcols if not tolerances.ignored(config, file, c)]
            akeep = [c for c in acols if not tolerances.ignored(config, file, c)]
            missing = [c for c in rkeep if c not in akeep]
            extra = [c for c in akeep if c not in rkeep]
            if missing:
                yield ("structure", f"{config}: {file}: columns missing in the run: {', '.join(missing)}")
            if extra:
                yield ("structure", f"{config}: {file}: columns not in the reference: {', '.join(extra)}")
            if len(rrows) != len(arows):
                yield ("structure", f"{config}: {file}: {len(arows)} rows, the reference has {len(rrows)}")
                continue
            ri = {c: i for i, c in enumerate(rcols)}
            ai = {c: i for i, c in enumerate(acols)}
            label = rcols[0]  # t for monitors.csv, size for the REV tables
            for c in rkeep:
                if c not in ai:
                    continue
                rule = tolerances.rule(config, file, c)
                for n, (rrow, arow) in enumerate(zip(rrows, arows)):
                    yield ("value", file, c, f"row {n} ({label} = {_fmt(rrow[0])})", rrow[ri[c]], arow[ai[c]],
                           rule)
        else:
            _, rstatus, rvalues = reference[file]
            _, astatus, avalues = actual[file]
            if rstatus != astatus:
                yield ("structure", f"{config}: {file}: status '{astatus}', the reference has '{rstatus}'")
            for key in sorted(rvalues):
                if tolerances.ignored(config, file, key):
                    continue
                now = key if key in avalues else tolerances.renamed.get(key, key)
                if now not in avalues:
                    yield ("structure", f"{config}: {file}: {key} is in the reference, not in the run")
                else:
                    yield ("value", file, key, "end", rvalues[key], avalues[now],
                           tolerances.rule(config, file, key))


def compare_results(config, reference, actual, tolerances, max_reports=20):
    """List of failure messages (empty: the results match)."""
    failures = []
    for p in pairs(config, reference, actual, tolerances):
        if p[0] == "structure":
            failures.append(p[1])
            continue
        _, file, key, where, ref, act, rule = p
        ok, diff, tol = compare_value(ref, act, rule["atol"], rule["rtol"])
        if not ok:
            how = (f"difference {diff:.3g}, tolerance {tol:.3g}" if not math.isnan(diff)
                   else "must match exactly (NaN/null, booleans, infinities)")
            failures.append(f"{config}: {file}: {key} at {where}: reference {_fmt(ref)}, actual {_fmt(act)}, {how}")
    if len(failures) > max_reports:
        failures = failures[:max_reports] + [f"{config}: ... and {len(failures) - max_reports} more"]
    return failures


def compare(output_dir, name, references=DEFAULT_REFERENCES):
    """Failure messages of comparing OUTPUT_DIR with reference NAME (empty: ok)."""
    references = pathlib.Path(references)
    ref_dir = references / name
    if not ref_dir.is_dir():
        return [f"{name}: no reference in {ref_dir} (make one with --update)"]
    tolerances = Tolerances(references / TOLERANCES)
    reference = read_reference(ref_dir)
    if not reference:
        return [f"{name}: the reference folder {ref_dir} holds no results"]
    try:
        actual = read_output(output_dir)
    except (OSError, ValueError) as e:
        return [f"{name}: cannot read the output in {output_dir}: {e}"]
    return compare_results(name, reference, actual, tolerances)


# ---------------------------------------------------------------- updating


def update(output_dir, name, references=DEFAULT_REFERENCES):
    """Stores the results of OUTPUT_DIR as reference NAME (replacing it), without
    the keys and columns the tolerances ignore (timings)."""
    references = pathlib.Path(references)
    tolerances = Tolerances(references / TOLERANCES)
    actual = read_output(output_dir)
    if not actual:
        raise RuntimeError(f"{output_dir} holds no results to store")
    ref_dir = references / name
    if ref_dir.exists():
        shutil.rmtree(ref_dir)
    ref_dir.mkdir(parents=True)
    for file, entry in actual.items():
        if entry[0] == "csv":
            # The text of the run's file (exact values as written), less ignored columns.
            with open(pathlib.Path(output_dir) / file, newline="") as f:
                lines = [line for line in csv.reader(f) if line]
            keep = [i for i, c in enumerate(lines[0]) if not tolerances.ignored(name, file, c.strip())]
            with open(ref_dir / file, "w", newline="") as f:
                w = csv.writer(f, lineterminator="\n")
                for line in lines:
                    w.writerow([line[i] for i in keep])
        else:
            _, status, values = entry
            kept = {k: v for k, v in values.items() if not tolerances.ignored(name, file, k)}
            (ref_dir / file).write_text(json.dumps({"status": status, "values": kept}, indent=1) + "\n")
    return sorted(actual)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("output_dir")
    p.add_argument("name", help="<config stem>_<k>")
    p.add_argument("--references", default=str(DEFAULT_REFERENCES))
    p.add_argument("--update", action="store_true", help="store OUTPUT_DIR as the reference")
    a = p.parse_args()
    if a.update:
        files = update(a.output_dir, a.name, a.references)
        print(f"{a.name}: reference updated ({', '.join(files)})")
        return 0
    failures = compare(a.output_dir, a.name, a.references)
    for f in failures:
        print(f, file=sys.stderr)
    if not failures:
        print(f"{a.name}: matches the reference")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
