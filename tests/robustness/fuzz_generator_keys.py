#!/usr/bin/env python3
"""Generator-key fuzzer (issue 35, item 3): no value of a rock-mass generator's
numeric key may keep `fissure validate` busy for long or make it big.

Every scene of configs/ with a generator — `rock_mass` (joint sets, DFN
families, excavations, explicit fractures, the domain) and the DFN of a REV
study (`network.dfn`) — is the base of cases that set its numeric generator
keys to values over many orders of magnitude, in SI units:

  length     spacings, spreads, trace and bridge lengths, length-law
             parameters, apertures, circle radii, merge tolerance, REV
             region, fracture end coordinates: 1e-6 .. 1e9 m
  p20, p21   DFN densities: 1e-6 .. 1e9 1/m^2, 1/m
  count      circle segments, max_blocks, max_fractures, seeds: 1 .. 1e9
  exponent   power-law and aperture exponents: 0 .. 1e3, also 1 -+ 1e-6
  kappa      von Mises concentration: 0 .. 1e9
  fraction   phase, stagger: 0 .. 1
  scale      the domain (and its excavations and fractures) times 1e-6 .. 1e6

The grid is every single key at each of its values; on top, --combos seeded
cases set 2 or 3 keys of one scene at once to log-uniform values. By
default a seeded sample of --cases of the grid is run (the ctest); --all runs
all of it.

Each case runs `fissure validate SCENE` (a REV study, which `validate` does
not read, `fissure rev STUDY --realizations 1 -j 1 --no-plots -q`) under a
--memory-mb address-space limit (RLIMIT_AS). It fails (exit 1) when it

  SLOW       takes more than --max-seconds CPU seconds (the wall time of a
             shared machine says little: it is reported, and a case that
             waits more than 5x that + 30 s of wall time is killed, SLOW too)
  BIG        peaks above --memory-mb of resident memory, or fails to allocate
             under the limit (std::bad_alloc, ...)
  CRASH      is killed by a signal
  UNLOCATED  exits with an error whose lines do not all say FILE:LINE:COLUMN

and passes when it is REJECTED (every error located) or ACCEPTED. The report
(report.json, cases.csv in --out) lists every case with its CPU and wall
seconds and peak memory (ru_maxrss), and names the slowest and biggest.

Usage: fuzz_generator_keys.py [--fissure build/app/fissure] [--configs configs]
       [--out DIR] [--cases N | --all] [--combos N] [--seed S] [--jobs J]
       [--max-seconds 10] [--memory-mb 2048] [--quiet]

Needs Python 3 with PyYAML (Debian: python3-yaml).
"""
import argparse
import copy
import csv
import json
import math
import multiprocessing
import random
import re
import shutil
import sys
import time
from pathlib import Path

import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fuzz_common import OOM_PATTERN, located, run_measured  # noqa: E402

REPO = Path(__file__).resolve().parents[2]

DECADES = [1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9]
VALUES = {
    "length": DECADES,
    "p20": DECADES,
    "p21": DECADES,
    "count": [1, 3, 1000, 10**6, 10**9],
    "exponent": [0, 1e-6, 1 - 1e-6, 1, 1 + 1e-6, 2, 3, 10, 1e3],
    "kappa": [0, 1e-6, 1.0, 1e3, 1e6, 1e9],
    "fraction": [0, 1e-9, 0.5, 1 - 1e-9, 1],
    "scale": [1e-6, 1e-3, 1e3, 1e6],
}
UNIT = {"length": "m", "p20": "1/m^2", "p21": "1/m"}
# Log-uniform ranges of the combined cases.
RANGES = {"length": (1e-6, 1e9), "p20": (1e-6, 1e9), "p21": (1e-6, 1e9), "count": (1, 1e9),
          "exponent": (0, 10), "kappa": (0, 1e9), "fraction": (0, 1), "scale": (1e-6, 1e6)}

# The kind of a generator key from its name (and, for `exponent`, it is an
# exponent whichever law it belongs to). Angles and names are not fuzzed.
KIND_OF_KEY = {
    "spacing": "length", "spacing_spread": "length", "trace_length": "length",
    "bridge_length": "length", "aperture": "length", "value": "length", "min": "length",
    "max": "length", "mean": "length", "std": "length", "factor": "length",
    "radius": "length", "merge_tolerance": "length", "region": "length",
    "p20": "p20", "p21": "p21", "segments": "count", "max_blocks": "count",
    "max_fractures": "count", "seed": "count", "exponent": "exponent", "kappa": "kappa",
    "phase": "fraction", "stagger": "fraction",
}
NUMBER = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(\s+\S.*)?$")


def load(text):
    return yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


def dump(tree):
    return yaml.dump(tree, Dumper=getattr(yaml, "CSafeDumper", yaml.SafeDumper),
                     sort_keys=False, default_flow_style=None, width=100)


def numeric(v):
    if isinstance(v, bool):
        return False
    return isinstance(v, (int, float)) or (isinstance(v, str) and NUMBER.match(v) is not None)


def generator_keys(tree):
    """(path, kind) of every numeric generator key of a scene or REV study."""
    keys = []

    def visit(node, path):
        if isinstance(node, dict):
            for k, v in node.items():
                p = path + (k,)
                if k == "orientation" and isinstance(v, dict):  # only kappa, not the angles
                    if numeric(v.get("kappa")):
                        keys.append((p + ("kappa",), "kappa"))
                elif k in ("from", "to") and isinstance(v, list):  # the first fracture's ends
                    if path[-1] == 0:
                        keys.extend((p + (i,), "length") for i in range(len(v)) if numeric(v[i]))
                elif k == "length" and numeric(v):  # `length: 5 m`, a constant
                    keys.append((p, "length"))
                elif k in KIND_OF_KEY and numeric(v):
                    keys.append((p, KIND_OF_KEY[k]))
                elif k not in ("domain", "vertices", "centre", "fixed_blocks", "initial_stress"):
                    visit(v, p)
        elif isinstance(node, list):
            for i, v in enumerate(node):
                visit(v, path + (i,))

    if isinstance(tree.get("rock_mass"), dict):
        visit(tree["rock_mass"], ("rock_mass",))
        # The section's own counts and sizes, also where the scene leaves them out.
        for k in ("seed", "merge_tolerance", "max_blocks", "max_fractures"):
            if k not in tree["rock_mass"]:
                keys.append((("rock_mass", k), KIND_OF_KEY[k]))
        keys.append((("rock_mass", "domain"), "scale"))
    network = tree.get("network")
    if isinstance(network, dict) and isinstance(network.get("dfn"), dict):
        visit(network["dfn"], ("network", "dfn"))
    return keys


def get(tree, path):
    for k in path:
        tree = tree[k]
    return tree


def put(tree, path, value):
    get(tree, path[:-1])[path[-1]] = value


def text_of(kind, value):
    """The YAML value: SI number with its unit; whole numbers for counts."""
    if kind == "count":
        return int(value)
    if kind in UNIT:
        return f"{value:.6g} {UNIT[kind]}"
    return float(f"{value:.9g}")


def scaled(points, f):
    return [[value_of(c) * f for c in p] for p in points]


def apply(tree, path, kind, value):
    if kind == "scale":  # the domain, and what must lie in it, scaled about the origin
        rock = tree["rock_mass"]
        rock["domain"] = scaled(rock["domain"], value)
        for e in rock.get("excavations") or []:
            if "vertices" in e:
                e["vertices"] = scaled(e["vertices"], value)
            if "circle" in e:
                e["circle"]["centre"] = scaled([e["circle"]["centre"]], value)[0]
                e["circle"]["radius"] = f"{value_of(e['circle']['radius']) * value:.6g} m"
        for f in rock.get("fractures") or []:
            f["from"], f["to"] = scaled([f["from"]], value)[0], scaled([f["to"]], value)[0]
        return
    put(tree, path, text_of(kind, value))


def value_of(v):
    """A plain number, or the SI value of 'NUMBER UNIT' for the length units
    the configs use."""
    if isinstance(v, (int, float)):
        return float(v)
    number, unit = re.match(r"^\s*(\S+?)\s*([a-z]*)\s*$", v).groups()
    return float(number) * {"mm": 1e-3, "cm": 1e-2, "um": 1e-6, "km": 1e3}.get(unit, 1)


class Base:
    def __init__(self, path):
        self.path = path
        self.name = path.stem
        self.text = path.read_text()
        header = [l for l in self.text.splitlines() if l.startswith("#")]
        ci = [l for l in header if l.startswith("# CI:")]
        self.mode = "rev" if ci and ci[0].split()[3:4] == ["rev"] else "validate"
        self.tree = load(self.text)
        self.keys = generator_keys(self.tree) if isinstance(self.tree, dict) else []


def grid(bases):
    cases = []
    for b in bases:
        for path, kind in b.keys:
            for v in VALUES[kind]:
                cases.append({"base": b.name, "set": [[list(path), kind, v]]})
    return cases


def combos(bases, n, seed):
    rng = random.Random(f"combos:{seed}")
    cases = []
    with_keys = [b for b in bases if len(b.keys) >= 2]
    for _ in range(n):
        b = rng.choice(with_keys)
        chosen = rng.sample(b.keys, min(len(b.keys), rng.choice([2, 3])))
        settings = []
        for path, kind in chosen:
            lo, hi = RANGES[kind]
            if kind == "fraction":
                v = rng.uniform(lo, hi)
            elif lo == 0:
                v = 0 if rng.random() < 0.1 else 10 ** rng.uniform(-6, math.log10(hi))
            else:
                v = 10 ** rng.uniform(math.log10(lo), math.log10(hi))
            settings.append([list(path), kind, round(v) if kind == "count" else v])
        cases.append({"base": b.name, "set": settings})
    return cases


def describe(case):
    return "; ".join(f"{'.'.join(map(str, p))} = {text_of(k, v)}" for p, k, v in case["set"])


def run_limited(args, cwd, max_seconds, memory_mb):
    """Runs `args` under the limits (CPU past the criterion, so that a slow
    case reports its time); fuzz_common.run_measured's record."""
    r = run_measured(args, cwd, 2 * max_seconds + 5, 5 * max_seconds + 30, memory_mb)
    return {"rc": r["rc"], "cpu": r["cpu_seconds"], "wall": r["seconds"], "rss_mb": r["rss_mb"],
            "stderr": r["stderr"], "killed": r["timed_out"]}


def classify(r, scene_name, max_seconds, memory_mb):
    first = next((l for l in r["stderr"].splitlines() if l.strip()), "")
    if r["killed"] or r["cpu"] > max_seconds:
        return "SLOW", f"{r['cpu']:.1f} CPU s ({r['wall']:.1f} s wall); {first}"
    if r["rss_mb"] > memory_mb or (r["rc"] != 0 and OOM_PATTERN.search(r["stderr"])):
        return "BIG", f"{r['rss_mb']:.0f} MB; {first}"
    if r["rc"] < 0:
        return "CRASH", f"signal {-r['rc']}; {first}"
    if r["rc"] == 0:
        return "ACCEPTED", ""
    bad = located(r["stderr"], scene_name)
    if bad:
        return "UNLOCATED", bad[0][:300]
    body = [l for l in r["stderr"].splitlines() if re.match(re.escape(scene_name) + r":\d+:\d+: ", l)]
    return "REJECTED", (body[0] if body else first)[:300]


WORKER = {}


def run_case(index):
    args, bases, case = WORKER["args"], WORKER["bases"], WORKER["cases"][index]
    base = bases[case["base"]]
    folder = Path(args.out) / "cases" / f"{index:05d}"
    folder.mkdir(parents=True, exist_ok=True)
    tree = copy.deepcopy(base.tree)
    for path, kind, value in case["set"]:
        apply(tree, tuple(path), kind, value)
    scene = folder / f"{base.name}.yaml"
    scene.write_text(dump(tree))
    if base.mode == "rev":
        command = [args.fissure, "rev", scene.name, "-o", "out", "--realizations", "1", "-j", "1",
                   "--no-plots", "-q"]
    else:
        command = [args.fissure, "validate", scene.name]
    r = run_limited(command, folder, args.max_seconds, args.memory_mb)
    cls, message = classify(r, scene.name, args.max_seconds, args.memory_mb)
    result = {"case": index, "base": base.name, "command": base.mode, "set": describe(case),
              "class": cls, "rc": r["rc"], "cpu_seconds": r["cpu"], "wall_seconds": r["wall"],
              "peak_mb": r["rss_mb"], "message": message}
    if cls in ("ACCEPTED", "REJECTED"):
        shutil.rmtree(folder, ignore_errors=True)
    else:
        (folder / "case.json").write_text(json.dumps(result, indent=1))
    return result


FAILING = ["SLOW", "BIG", "CRASH", "UNLOCATED"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--fissure", default=str(REPO / "build" / "app" / "fissure"))
    p.add_argument("--configs", default=str(REPO / "configs"))
    p.add_argument("--out", default=str(REPO / "out" / "fuzz_generator_keys"))
    p.add_argument("--cases", type=int, default=400, help="grid cases sampled (seeded)")
    p.add_argument("--all", action="store_true", help="the whole grid")
    p.add_argument("--combos", type=int, default=60, help="cases with 2-3 keys set at once")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--max-seconds", type=float, default=10, help="CPU seconds per case")
    p.add_argument("--memory-mb", type=int, default=2048, help="address space and peak memory")
    p.add_argument("--quiet", action="store_true")
    args = p.parse_args()
    if not Path(args.fissure).is_file():
        print(f"fuzz_generator_keys: no fissure executable at {args.fissure}", file=sys.stderr)
        return 2
    args.fissure = str(Path(args.fissure).resolve())  # the cases run in their folders
    bases = {b.name: b for b in (Base(f) for f in sorted(Path(args.configs).glob("*.yaml")))
             if b.keys}
    cases = grid(bases.values())
    full = len(cases)
    if not args.all and args.cases < len(cases):
        cases = random.Random(f"grid:{args.seed}").sample(cases, args.cases)
    cases += combos(bases.values(), args.combos, args.seed)
    out = Path(args.out)
    shutil.rmtree(out / "cases", ignore_errors=True)
    (out / "cases").mkdir(parents=True)
    WORKER.update(args=args, bases=bases, cases=cases)
    start = time.monotonic()
    results = []
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        for r in pool.imap_unordered(run_case, range(len(cases))):
            results.append(r)
            if not args.quiet and (r["class"] in FAILING or len(results) % 100 == 0):
                print(f"[{len(results)}/{len(cases)} {time.monotonic() - start:.0f}s] "
                      f"{r['class']} {r['base']}: {r['set']}: {r['message'][:200]}", flush=True)
    results.sort(key=lambda r: r["case"])
    counts = {c: sum(r["class"] == c for r in results)
              for c in FAILING + ["REJECTED", "ACCEPTED"]}
    slowest = max(results, key=lambda r: r["cpu_seconds"])
    biggest = max(results, key=lambda r: r["peak_mb"])
    report = {"cases": len(results), "grid": full, "bases": sorted(bases),
              "keys": sum(len(b.keys) for b in bases.values()), "classes": counts,
              "max_seconds": args.max_seconds, "memory_mb": args.memory_mb,
              "slowest": slowest, "biggest": biggest,
              "wall_seconds": round(time.monotonic() - start, 1),
              "failures": [r for r in results if r["class"] in FAILING]}
    (out / "report.json").write_text(json.dumps(report, indent=1))
    with open(out / "cases.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)
    print(f"fuzz_generator_keys: {len(results)} cases ({report['keys']} keys of "
          f"{len(bases)} scenes; grid {full}) in {report['wall_seconds']:.0f} s: "
          + ", ".join(f"{n} {c}" for c, n in counts.items() if n))
    print(f"  slowest: {slowest['cpu_seconds']:.2f} CPU s ({slowest['wall_seconds']:.2f} s wall), "
          f"{slowest['base']}: {slowest['set']} ({slowest['class']})")
    print(f"  biggest: {biggest['peak_mb']:.0f} MB, {biggest['base']}: {biggest['set']} "
          f"({biggest['class']})")
    for r in report["failures"]:
        print(f"  {r['class']} case {r['case']} {r['base']}: {r['set']}: {r['message'][:200]}")
    return 1 if report["failures"] else 0


if __name__ == "__main__":
    sys.exit(main())
