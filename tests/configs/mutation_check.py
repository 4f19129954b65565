#!/usr/bin/env python3
"""Checks that the regression references catch small changes of a scene.

A tolerance wide enough to hold on every machine must still be narrow enough to
see a change of the physics (tests/configs/README.md, "It fails when it
should"). For every config in configs/ with a `# CI:` line and a reference, this
script makes mutants of the scene, each with ONE value changed:

* every number of every `materials` entry, top-level or a module's
  (density, moduli, Poisson's ratio, conductivities, permeabilities, ...), of
  every `joints` entry (cohesion, strengths), of the `fluid`, of the flow's
  joint law (`hm`: normal stiffness, dilation) and of fracture `aperture`
  laws, times 1.001 (+0.1 %);
* every `friction_angle` (wherever it is) + 0.01 deg;

runs the config's CI lines on each mutant and compares their output with the
config's references (compare_with_reference.py). A mutant must fail the
comparison of one of them ("caught": thermal_wedge's short line pins the
elastic constants that its long, stick-slip line compares only at the
precision its chaos leaves), unless its output is identical, to the last bit, to the
unchanged scene's output of the same binary: then the value does not enter the
CI line's results at all (a density without gravity, a joint no contact uses
within the CI line's steps) and no comparison could see it ("no effect").
A mutant whose results moved, but by no more than round-off (every value within
1e-10 of its quantity's scale of the unchanged output: a layer's heat capacity
in steps that never heat it), is "round-off only". A mutant whose results
changed beyond that but that passes the comparison is MISSED: the tolerances
are too wide, and the script exits 1.

The mutants are edited as text (the one number replaced in place), so that
comments, units and layout stay as the user wrote them; each is run from a
copy of configs/ so that files the scene names resolve as for the original.

Usage: mutation_check.py FISSURE SOURCE_DIR OUTPUT_DIR [--configs STEM ...] [--jobs N] [--reuse]
Needs PyYAML (Debian's python3-yaml) for the node positions.
"""
import argparse
import concurrent.futures
import filecmp
import json
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

import yaml

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_with_reference as C  # noqa: E402

NUMBER = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(\s*[A-Za-z^/*0-9.\-]*)\s*$")
RELATIVE_CHANGE = 1e-3  # +0.1 % of a material value
FRICTION_CHANGE = 0.01  # deg
# A mutant whose results moved by less than this share of each quantity's
# scale changed them only as round-off does: the measured tolerances' floor
# (measure_spread.py's FLOOR).
ROUND_OFF = 1e-10
# Keys of a materials/joints entry that are not physical values.
NOT_VALUES = {"name", "model", "type", "law", "material", "distribution", "source", "scheme"}
# Sections whose numbers are material values, at any depth of the scene.
VALUE_SECTIONS = {"materials", "joints", "fluid", "hm", "aperture"}
RESULT_FILES = ("monitors.csv", "summary.json", "rev.json", "sizes.csv", "fits.csv", "domains.csv")


def mutation_sites(text):
    """[(description, start, end, new text)] of the scene text's values to mutate."""
    root = yaml.compose(text)
    sites = []

    def scalar_site(path, node, friction):
        if not isinstance(node, yaml.ScalarNode):
            return
        m = NUMBER.match(node.value)
        if not m:
            return
        number, unit = m.group(1), m.group(2)
        value = float(number)
        if friction:
            if unit.strip() not in ("", "deg"):
                return
            new = f"{value + FRICTION_CHANGE:.10g}{unit}"
            what = f"{path} {node.value} -> {new} (+{FRICTION_CHANGE} deg)"
        else:
            if value == 0:
                return
            new = f"{value * (1 + RELATIVE_CHANGE):.12g}{unit}"
            what = f"{path} {node.value} -> {new} (+0.1 %)"
        quote = text[node.start_mark.index] if text[node.start_mark.index] in "'\"" else ""
        sites.append((what, node.start_mark.index, node.end_mark.index, f"{quote}{new}{quote}"))

    def walk(node, path, in_entry):
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                k = key.value if isinstance(key, yaml.ScalarNode) else "?"
                sub = f"{path}.{k}" if path else k
                if k == "friction_angle":
                    scalar_site(sub, value, friction=True)
                elif in_entry and k not in NOT_VALUES and isinstance(value, yaml.ScalarNode):
                    scalar_site(sub, value, friction=False)
                else:
                    walk(value, sub, in_entry or k in VALUE_SECTIONS)
        elif isinstance(node, yaml.SequenceNode):
            for i, item in enumerate(node.value):
                walk(item, f"{path}[{i}]", in_entry)

    if root is not None:
        walk(root, "", False)
    return sites


def ci_lines(config):
    header = [l for l in config.read_text().splitlines() if l.startswith("#")]
    return [l.split(":", 1)[1].strip() for l in header if l.startswith("# CI:")]


def run_line(app, line, cwd, folder):
    words = shlex.split(line)
    words[0] = app
    shutil.rmtree(folder, ignore_errors=True)
    words += ["-o", str(folder), "--no-plots"] if words[1] == "run" and "--no-plots" not in words else ["-o", str(folder)]
    return subprocess.run(words, cwd=cwd, capture_output=True, text=True).returncode


def same_results(a, b):
    for name in RESULT_FILES:
        fa, fb = pathlib.Path(a) / name, pathlib.Path(b) / name
        if fa.is_file() != fb.is_file():
            return False
        if fa.is_file() and name.endswith(".csv") and not filecmp.cmp(fa, fb, shallow=False):
            return False
        if fa.is_file() and name.endswith(".json"):
            strip = lambda p: {k: v for k, v in C.flatten(json.loads(p.read_text())).items()
                               if "seconds" not in k}
            if strip(fa) != strip(fb):
                return False
    return True


def round_off_only(name, base, out):
    """True if every pinned value of OUT lies within ROUND_OFF S of BASE's, S the
    largest |value| of BASE under the same tolerance rule: the change reached
    the results only as round-off (a heat capacity of a layer the CI line's
    steps never heat, whose value still enters the assembled matrix)."""
    tolerances = C.Tolerances(C.DEFAULT_REFERENCES / C.TOLERANCES)
    groups = {}
    for pr in C.pairs(name, C.read_output(base), C.read_output(out), tolerances):
        if pr[0] == "structure":
            return False
        ref, act, rule = pr[4], pr[5], pr[6]
        if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in (ref, act)):
            if ref != act:
                return False
            continue
        groups.setdefault(id(rule), []).append((float(ref), float(act)))
    for values in groups.values():
        scale = max(abs(r) for r, _ in values)
        if any(abs(r - a) > ROUND_OFF * scale for r, a in values):
            return False
    return True


def line_verdict(app, source, work, name, config, text, mutant, line, reuse):
    """The verdict of one CI line on one mutant (n, (what, start, end, new))."""
    n, (what, start, end, new) = mutant
    base = work / "baseline"
    tree = work / f"mutant_{n}"
    out = tree / "out"
    if reuse and any((out / f).is_file() for f in ("summary.json", "rev.json")):
        rc = 0  # --reuse: compare the stored output again (after a change of the tolerances)
    else:
        shutil.rmtree(tree, ignore_errors=True)
        shutil.copytree(source / "configs", tree / "configs", symlinks=True)
        (tree / "configs" / config.name).write_text(text[:start] + new + text[end:])
        rc = run_line(app, line, tree, out)
        shutil.rmtree(tree / "configs", ignore_errors=True)
    if rc != 0:
        return "caught", f"caught by {name} (the run exited {rc})"
    if same_results(base, out):
        return "no effect", "no effect (results identical to the last bit)"
    failures = C.compare(out, name)
    if failures:
        return "caught", f"caught by {name}: {failures[0].split(': ', 1)[1][:150]}"
    if round_off_only(name, base, out):
        return "round-off", f"round-off only (every value within {ROUND_OFF:g} of its scale of the unchanged run's)"
    return "missed", "MISSED"


def check_config(app, source, output, config, lines, reuse):
    """Every mutant of CONFIG against every CI line of it: caught when one line's
    comparison fails (a short line can pin what a long, chaotic one cannot)."""
    text = config.read_text()
    works = []
    for k, line in enumerate(lines):
        name = f"{config.stem}_{k}"
        work = output / name
        if not reuse:
            shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True, exist_ok=True)
        base = work / "baseline"
        done = reuse and any((base / f).is_file() for f in ("summary.json", "rev.json"))
        rc = 0 if done else run_line(app, line, source, base)
        if rc != 0:
            return config.stem, [f"{name}: the unchanged CI line exited {rc}"], []
        works.append((name, work, line))
    rows, missed = [], []
    for mutant in enumerate(mutation_sites(text)):
        what = mutant[1][0]
        verdicts = [line_verdict(app, source, work, name, config, text, mutant, line, reuse)
                    for name, work, line in works]
        kinds = [v[0] for v in verdicts]
        if "caught" in kinds:
            verdict = verdicts[kinds.index("caught")][1]
        elif "missed" in kinds:
            verdict = "MISSED"
            missed.append(f"{config.stem}: {what}: results changed but the comparison passes")
        elif "round-off" in kinds:
            verdict = verdicts[kinds.index("round-off")][1]
        else:
            verdict = verdicts[0][1]
        rows.append(f"{config.stem}: {what}: {verdict}")
    return config.stem, missed, rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fissure")
    p.add_argument("source")
    p.add_argument("output")
    p.add_argument("--configs", nargs="*", help="config stems (default: all)")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--reuse", action="store_true",
                   help="compare the outputs a previous run left in OUTPUT_DIR again instead of running")
    a = p.parse_args()
    app = str(pathlib.Path(a.fissure).resolve())
    source, output = pathlib.Path(a.source).resolve(), pathlib.Path(a.output).resolve()
    jobs = []
    for config in sorted((source / "configs").glob("*.yaml")):
        if a.configs and config.stem not in a.configs:
            continue
        if ci_lines(config):
            jobs.append((config, ci_lines(config)))
    missed_all, caught, no_effect = [], 0, 0
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for name, missed, rows in pool.map(lambda j: check_config(app, source, output, *j, a.reuse), jobs):
            for r in rows:
                print(r, flush=True)
            caught += sum(1 for r in rows if ": caught" in r)
            no_effect += sum(1 for r in rows if ": no effect" in r or ": round-off only" in r)
            missed_all += missed
    print(f"{caught} mutants caught, {no_effect} without effect on the CI line's results beyond round-off, "
          f"{len(missed_all)} missed")
    for m in missed_all:
        print(m, file=sys.stderr)
    return 1 if missed_all else 0


if __name__ == "__main__":
    sys.exit(main())
