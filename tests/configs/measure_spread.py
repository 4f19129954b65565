#!/usr/bin/env python3
"""Measures how far runs of the CI lines lie from the stored references, per
config and tolerance rule: the numbers behind references/tolerances.json.

Each RUNS folder holds output folders named like the references
(<config stem>_<k>/), e.g. the OUTPUT_DIR of run_config_ci_lines.py, or a
folder per repetition, build or machine. For every config and every rule of
tolerances.json that applies to it, prints

  n        values compared (all runs, all rows)
  max|d|   largest absolute difference from the reference
  max rel  largest |d| / |reference| over the values whose |reference| is at
           least 1e-6 of the largest |reference| of that rule in that config
  |d|/S    largest |d| / S, S the largest |reference| of the rule in that config
           (the difference against the scale of the quantity: for values near 0)
  use      largest |d| / (atol + rtol |reference|): the share of the tolerance
           used (> 1: the comparison fails; "exact" when both are 0 and no value
           differs)
  fails    values outside the tolerance

and the structural differences (rows, columns, keys, status, NaN).

With --suggest it prints instead, for every rule of tolerances.json whose
"basis" is "measured", the tolerance the measurement gives (README.md,
"Tolerances") where it differs from the file:

  rtol = R(margin x max rel), over the values whose |reference| >= 1e-6 S
         (at least the floor 1e-10);
  atol = R(max over all values of margin |d| - rtol |reference|), at least
         R(1e-10 S) unless the rule says "scale_floor": false;
  "atol_only": rtol = 0, atol = R(margin max |d|);
  or, where it is the smaller at S: rtol = 1e-10, atol = R(margin max |d|)
  (a quantity whose values pass through 0, where round-off is absolute);

with margin 100 unless the rule gives one, and R() rounding up to 1, 2, 5
times a power of 10; with --write it stores them, and the measurement behind
them ("measured": runs, largest |d| and relative difference), in
tolerances.json. A suggested tolerance above 1e-5 relative (or 1e-5 S) is
flagged WIDE (atol + rtol S above 1e-5 S): it may hide a change of 0.1 % in a material value, so such a
quantity needs a rule of basis "physics" (mutation_check.py shows whether the
config's other values still catch the change). Rules of basis "print" (one
unit of the last printed digit), "physics" and "exact" are reported when a
value uses more than 1/10 of them.

Usage: measure_spread.py RUNS... [--references DIR] [--all] [--keys] [--suggest [--write]]
  --all      also rules whose values never differ
  --keys     one line per key instead of per rule
  --suggest  the tolerances the measurement gives, where they differ from the file
  --write    with --suggest: store them in tolerances.json
"""
import argparse
import collections
import json
import math
import re
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_with_reference as C  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--references", default=str(C.DEFAULT_REFERENCES))
    p.add_argument("--all", action="store_true")
    p.add_argument("--keys", action="store_true")
    p.add_argument("--suggest", action="store_true")
    p.add_argument("--write", action="store_true")
    a = p.parse_args()
    if a.suggest:
        return suggest(a)
    references = pathlib.Path(a.references)
    tolerances = C.Tolerances(references / C.TOLERANCES)
    names = sorted(d.name for d in references.iterdir() if d.is_dir())
    for name in names:
        reference = C.read_reference(references / name)
        groups = collections.OrderedDict()  # label -> list of (ref, d, tol, rule)
        structure = collections.Counter()
        runs = 0
        for folder in a.runs:
            out = pathlib.Path(folder) / name
            if not out.is_dir():
                continue
            runs += 1
            for pr in C.pairs(name, reference, C.read_output(out), tolerances):
                if pr[0] == "structure":
                    structure[pr[1]] += 1
                    continue
                _, file, key, where, ref, act, rule = pr
                label = key if a.keys else rule.get("key", "*") + ("" if rule.get("config") is None else f" [{rule['config']}]")
                ok, d, tol = C.compare_value(ref, act, rule["atol"], rule["rtol"])
                if math.isnan(d):  # NaN, booleans, infinities: exact
                    d = 0.0 if ok else math.inf
                    ref = 0.0 if not isinstance(ref, (int, float)) or ref is None or math.isnan(ref) else ref
                groups.setdefault(label, []).append((float(ref), d, tol, ok))
        if runs == 0:
            continue
        print(f"== {name}: {runs} runs")
        for s, count in structure.items():
            print(f"   STRUCTURE ({count}x) {s}")
        for label, values in groups.items():
            dmax = max(v[1] for v in values)
            if dmax == 0 and not a.all:
                continue
            scale = max(abs(v[0]) for v in values)
            rel = max((v[1] / abs(v[0]) for v in values if abs(v[0]) >= 1e-6 * scale and v[0] != 0), default=0.0)
            over_s = dmax / scale if scale > 0 else math.inf if dmax > 0 else 0.0
            use = max((v[1] / v[2] if v[2] > 0 else (math.inf if v[1] > 0 else 0.0)) for v in values)
            fails = sum(1 for v in values if not v[3])
            use_s = "exact" if use == 0 and all(v[2] == 0 for v in values) else f"{use:.3g}"
            print(f"   {label:58s} n {len(values):5d}  max|d| {dmax:9.3g}  max rel {rel:9.3g}  "
                  f"|d|/S {over_s:9.3g}  S {scale:9.3g}  use {use_s:>6s}  fails {fails}")
    return 0


# The margin of a measured tolerance over the largest difference measured
# across builds, and the floor of values that never differed: the variants
# measured are samples of how results move when the order of floating-point
# operations changes; a user's instruction set that was not measured (AVX-512,
# another vectorizer) reorders them again and moves the results by the same
# kind of amount, not by the same amount (README.md, "Tolerances").
MARGIN = 100
FLOOR = 1e-10
# Beyond this a tolerance may hide a change of 0.1 % of a material value.
WIDE = 1e-5


def up125(x):
    """x rounded up to 1, 2 or 5 times a power of 10."""
    if x <= 0:
        return 0.0
    e = math.floor(math.log10(x))
    for m in (1, 2, 5, 10):
        if x <= m * 10.0**e * (1 + 1e-9):
            return float(f"{m}e{e}")


def tolerances_text(data):
    """tolerances.json as it is kept: one rule (and one renamed key) per line."""
    line = lambda v: json.dumps(v, ensure_ascii=False)
    renamed = ",\n".join(f"  {line(k)}: {line(v)}" for k, v in data.get("renamed", {}).items())
    rules = ",\n".join(f"  {line(r)}" for r in data["rules"])
    return f'{{\n "renamed": {{\n{renamed}\n }},\n "rules": [\n{rules}\n ]\n}}\n'


SUBJECTS = {"t": "output times", "simulated_time": "the end time", "*.[xy]": "monitor positions",
            "*.u[xy]": "monitor displacements", "*.v[xy]": "monitor velocities",
            "*.s[xy][xy]": "monitor block stresses", "*.p": "pressures", "*.T": "temperatures",
            "energy.*": "energy terms", "*.u?": "displacements", "*.s??": "stresses", "*.q?": "Darcy fluxes"}


def rule_subject(rule):
    """What a rule's values are, for its `why`: from the key, or the first clause of the old why."""
    if rule["key"] in SUBJECTS:
        return SUBJECTS[rule["key"]]
    first = rule.get("why", "").split(":")[0]
    if first and len(first) < 70 and not re.match(r"(widened|floor|identical|measured|\d)", first):
        return first
    return rule["key"]


def suggest(a):
    references = pathlib.Path(a.references)
    tolerances = C.Tolerances(references / C.TOLERANCES)
    values = collections.defaultdict(list)  # rule index -> (ref, d)
    runs = collections.Counter()
    for name in sorted(d.name for d in references.iterdir() if d.is_dir()):
        reference = C.read_reference(references / name)
        for folder in a.runs:
            out = pathlib.Path(folder) / name
            if not out.is_dir():
                continue
            runs[name] += 1
            for pr in C.pairs(name, reference, C.read_output(out), tolerances):
                if pr[0] == "structure":
                    print(f"STRUCTURE {pr[1]}")
                    continue
                _, file, key, where, ref, act, rule = pr
                ok, d, tol = C.compare_value(ref, act, 0, 0)
                if math.isnan(d):  # NaN, booleans, infinities: exact
                    if not ok:
                        print(f"DIFFERS {name} {file} {key} {where}: {ref!r} != {act!r}")
                    continue
                values[id(rule)].append((float(ref), d))
    print(f"runs per config: {dict(runs)}")
    changes = 0
    for rule in tolerances.rules:
        if rule.get("ignore"):
            continue
        vals = values.get(id(rule), [])
        label = f"{rule.get('config', '*')} {rule.get('file', '*')} {rule['key']}"
        basis = rule.get("basis", "exact")
        if basis != "measured":
            used = [v for v in vals if v[1] > 0.1 * (rule["atol"] + rule["rtol"] * abs(v[0]))]
            if used:
                changes += 1
                worst = max(used, key=lambda v: v[1] / max(rule["atol"] + rule["rtol"] * abs(v[0]), 1e-300))
                print(f"{label}: {len(used)} values use more than 1/10 of its {basis} tolerance, e.g. reference "
                      f"{worst[0]!r} |d| {worst[1]:.3g}")
            continue
        if not vals:
            print(f"{label}: no values")
            continue
        margin = rule.get("margin", MARGIN)
        scale = max(abs(v[0]) for v in vals)
        dmax = max(v[1] for v in vals)
        rel = max((v[1] / abs(v[0]) for v in vals if abs(v[0]) >= 1e-6 * scale and v[0] != 0), default=0.0)
        floor_atol = up125(FLOOR * scale) if rule.get("scale_floor", True) else 0.0
        if rule.get("atol_only"):
            rtol, atol = 0.0, up125(margin * dmax)
        else:
            # Relative: rtol from the largest relative difference, atol for what
            # it leaves (values near 0). Absolute: the floor's rtol, atol from the
            # largest difference (noise of a quantity that passes through 0).
            # The one with the smaller tolerance at the scale S of the values.
            rtol = max(up125(margin * rel), FLOOR)
            need = max(max(margin * v[1] - rtol * abs(v[0]), 0.0) for v in vals)
            atol = max(up125(need), floor_atol)
            absolute = max(up125(margin * dmax), floor_atol)
            if absolute + FLOOR * scale < atol + rtol * scale:
                rtol, atol = FLOOR, absolute
        second_cpu = re.search(r"widened for a second CPU \([^)]*\)[^;]*", rule.get("why", ""))
        if second_cpu:  # a difference seen on another machine, not in these runs: not narrowed below it
            atol, rtol = max(atol, float(rule["atol"])), max(rtol, float(rule["rtol"]))
        wide = (atol + rtol * scale) > WIDE * scale
        if wide:
            print(f"WIDE {label}: atol {atol:g} rtol {rtol:g} (max |d| {dmax:.3g}, max rel {rel:.3g}, S {scale:.3g})")
        if (atol, rtol) != (float(rule["atol"]), float(rule["rtol"])):
            changes += 1
            print(f"{label}: file atol {rule['atol']:g} rtol {rule['rtol']:g}, measurement gives atol {atol:g} rtol {rtol:g} "
                  f"({len(vals)} values, max |d| {dmax:.3g}, S {scale:.3g})")
        if a.write:
            rule["atol"], rule["rtol"] = atol, rtol
            what = rule_subject(rule)
            n = runs.get(rule.get("config"), max(runs.values(), default=0))
            where = f"in {n} runs of the builds of tests/configs/README.md, \"Measured spread\""
            if dmax == 0:
                floor = "rtol 1e-10 and atol 1e-10 S" if rule.get("scale_floor", True) else "rtol 1e-10"
                how = f"identical to the reference {where}: the floor, {floor} (S = {scale:.2g})"
            else:
                how = (f"margin {margin:g} over the largest difference from the reference {where} "
                       f"(max |d| {dmax:.2g}, max rel {rel:.2g}, S = {scale:.2g})")
            rule["why"] = f"{what}: {how}" + (f"; {second_cpu.group(0)}" if second_cpu else "")
            rule["measured"] = {"runs": runs[rule["config"]] if "config" in rule and rule["config"] in runs else
                                max(runs.values(), default=0), "max_abs": float(f"{dmax:.3g}"),
                                "max_rel": float(f"{rel:.3g}"), "scale": float(f"{scale:.3g}")}
    print(f"{changes} rules differ from the measurement")
    if a.write:
        path = references / C.TOLERANCES
        data = json.loads(path.read_text())
        data["rules"] = tolerances.rules
        path.write_text(tolerances_text(data))
        print(f"written: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
