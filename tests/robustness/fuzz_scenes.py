#!/usr/bin/env python3
"""Scene fuzzer (issue 22, item 7): mutates every scene in configs/ and runs it.

Each case takes one scene of configs/ (in turn), applies one to three
mutations, writes the result into its own case folder and runs the command
line on it under an address-space limit and a time-out:

  * `fissure validate SCENE`, then, if it is accepted,
    `fissure run SCENE -o OUT --max-steps K -q` (scenes whose `# CI:` line is
    `fissure run` or `fissure mesh`);
  * `fissure rev STUDY -o OUT --realizations 1 --no-plots -j 1 -q` for a REV
    study (its `# CI:` line is `fissure rev`; a study is not a scene, so
    `validate` does not apply), with the first of the CI line's `--states`
    and the two smallest sizes (`--sizes 0,1`) for a study under stress.

Mutations, chosen from the case's own seeded random generator (so case i of
seed s is the same on every machine, whatever else runs):

  structure (on the parsed YAML, written back with PyYAML): delete a key or a
    list item, duplicate a list item or a key (the same key twice in a map),
    huge / tiny / negative / non-finite numbers and units, wrong-typed values
    (a map, a list, a string, a boolean, an empty value where something else
    is expected), renamed and unknown keys, huge lists (an item repeated up to
    100,000 times), huge or degenerate polygons (up to 100,000 vertices,
    self-intersecting, zero area, repeated points), deep nesting, numbers
    times a modest factor, and keys of docs/scene-reference.md (and the REV
    study table of docs/flow.md) that the scene leaves out, set to a value of
    their type (so that valid scenes vary too and reach the run);
  text (on the raw bytes of the file, comments included): truncation, stray
    bytes (NUL, invalid UTF-8, control characters, YAML indicators), deleted,
    repeated, swapped or re-indented lines, very long lines (up to 2 MB), a
    byte-order mark, CR line ends, deep bracket nesting, an alias bomb.
  targeted (issue 35; a quarter of the structure operations): a number of the
    thermal, continuum or flow section made NaN, infinite, zero or negative;
    a mesh made 10-10,000 times finer with max_elements raised; a rock-mass
    or REV DFN generator key set over many orders of magnitude (the values
    of fuzz_generator_keys.py); PETSc options that PETSc refuses.
  --max-size caps lists and polygons (default 100,000); lines go to 20x that.

Checkpoint cases (6 % of the cases of a `fissure run` scene): the scene,
writing a checkpoint every step, runs its first steps once per fuzzer run
(OUT/checkpoints/SCENE); each case copies that output folder, corrupts its
checkpoint.h5 (1-16 flipped bytes anywhere or in the integrity record, up to
4 kB scrambled or zeroed, truncated, extended, another scene's checkpoint; one
case in nine leaves it intact) and runs `fissure run SCENE --restart
out/checkpoint.h5`.

A string value naming a file next to the scene (.yaml, .csv, .txt, .dat,
.json, .h5; configs/continuum_drained_tunnel.yaml names its REV study's
flow_rev_study/rev.json) is copied into the case folder, so that relative
paths keep working.

Classes (first match wins):

  CRASH       killed by a signal we did not send (SIGSEGV, SIGABRT from an
              uncaught exception, ...)
  HANG        still running after --timeout CPU seconds (SIGXCPU; CPU time
              so that a busy machine does not make hangs), or after 5 x that
              + 30 s of wall time (killed)
  OOM         out of memory under --memory-mb (std::bad_alloc and the like):
              an allocation that no estimate refused first
  OVER-BUDGET a generator case whose `validate` (a REV study: its one
              realization) took more than --validate-seconds CPU seconds or
              --validate-mb of peak resident memory (not under --sanitized)
  UNLOCATED   an error exit whose standard error does not say where in the
              scene the problem is: `error: invalid scene` followed by a line
              that is not `FILE:LINE:COLUMN: ...`, or any other error of
              `validate`; a run stopped by a scene problem ("...; expected
              ...") without FILE:LINE:COLUMN; an error of `run` that names
              neither a step, a time nor the process
  MISLEADING  an error that calls a key missing ("KEY: key is missing")
              which the scene has, with a value
  FLOOD       more than 150 lines of errors (a flood is summarized)
  NAN         a run (completed or stopped early) that wrote 'nan' or 'inf'
              into monitors.csv (apart from the documented pressure of a
              monitor off the fracture network), a non-finite value into
              summary.json (written as null: its monitors and energy) or
              results.h5; for a REV study, into its tables or rev.json (apart
              from the documented CV = inf of a size whose mean k is not
              positive)
  CORRUPT-ACCEPTED
              a restart from a corrupted checkpoint that ran (exit 0 or 2)
  OUTPUT-TOUCHED
              a refused restart that changed a file of the output folder
  INTACT-REFUSED
              a restart from an intact checkpoint that did not continue
  CHECKPOINT-NOT-WRITTEN
              the scene's first steps (2, 30 or 200) wrote no checkpoint
  VALIDATE-ACCEPTS-RUN-REJECTS
              `validate` exits 0 but `run` rejects the scene as invalid (with
              FILE:LINE:COLUMN), e.g. a flow boundary that no fracture of the
              generated network reaches
  RUNTIME-STOP
              the run stopped early (exit 2: diverged, failed after N steps,
              t = ...) with its reason: a diagnosis, not a crash
  REJECTED    `validate` rejected the scene, every line located (the goal)
  RAN         validate accepted it and the run ended normally

Every class above VALIDATE-ACCEPTS-RUN-REJECTS fails the run (exit 1;
--fail-on changes the list). A refused restart (exit 1, "the restart is
refused") that leaves the output folder as it was is REJECTED. Cases that are neither REJECTED nor RAN keep their folder with the
reproducer (the mutated scene, `case.json`, the commands' output); with
--minimise, one reproducer per distinct failure (class and normalised
message) that took at most 10 s is shrunk by deleting lines (and halving long
lines) while it still fails the same way, for at most --minimise-seconds. OK
cases' folders are deleted unless --keep-all.

The report (report.md, report.json in --out) counts the classes per source
scene and lists every bad case with its reproducer.

Usage:
  fuzz_scenes.py [--fissure build/app/fissure] [--configs configs] [--seed 1]
                 [--cases 300] [--out DIR] [--timeout 60] [--memory-mb 2048]
                 [--max-steps 3] [--jobs 2] [--minimise] [--case I ...]
                 [--validate-seconds 10] [--validate-mb 2048]

Needs Python 3 with PyYAML (Debian: python3-yaml); h5py and numpy (Debian:
python3-h5py) for the results.h5 check, else that check is skipped with a note.
"""
import argparse
import copy
import csv
import fcntl
import hashlib
import json
import math
import multiprocessing
import os
import random
import re
import shlex
import shutil
import signal
import sys
import time
from collections import Counter, defaultdict
from pathlib import Path

import yaml

import fuzz_common
import fuzz_generator_keys as generators
from fuzz_common import OOM_PATTERN, error_lines, located, run_measured

try:
    import h5py
    import numpy

    HAVE_H5PY = True
except ImportError:  # the results.h5 check is skipped (the report says so)
    HAVE_H5PY = False

REPO = Path(__file__).resolve().parents[2]

FAIL_DEFAULT = ["CRASH", "HANG", "OOM", "OVER-BUDGET", "UNLOCATED", "MISLEADING", "FLOOD",
                "NAN", "CORRUPT-ACCEPTED", "OUTPUT-TOUCHED", "INTACT-REFUSED",
                "CHECKPOINT-NOT-WRITTEN"]
CLASSES = FAIL_DEFAULT + ["VALIDATE-ACCEPTS-RUN-REJECTS", "RUNTIME-STOP", "REJECTED", "RAN"]
OK_CLASSES = {"REJECTED", "RAN"}

# ---------------------------------------------------------------------------
# YAML in and out


class Pairs(list):
    """A map written from a list of (key, value) pairs: a key may repeat."""


# libyaml's emitter when there is one (10-20x faster for the huge lists).
class SceneDumper(getattr(yaml, "CSafeDumper", yaml.SafeDumper)):
    def ignore_aliases(self, data):
        return True


SceneDumper.add_representer(
    Pairs, lambda d, data: d.represent_mapping("tag:yaml.org,2002:map", list(data)))


def dump(tree):
    return yaml.dump(tree, Dumper=SceneDumper, sort_keys=False, default_flow_style=None,
                     width=100, allow_unicode=True).encode("utf-8")


def load(text):
    return yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


# ---------------------------------------------------------------------------
# Source scenes


class Source:
    def __init__(self, path):
        self.path = path
        self.name = path.stem
        self.text = path.read_bytes()
        header = [l for l in self.text.decode("utf-8").splitlines() if l.startswith("#")]
        ci = [l.split(":", 1)[1].strip() for l in header if l.startswith("# CI:")]
        words = shlex.split(ci[0]) if ci else ["fissure", "run"]
        self.mode = "rev" if len(words) > 1 and words[1] == "rev" else "run"
        # A study under stress runs the first of its CI line's states and its
        # two smallest sizes only (`--states`, `--sizes`): with all five
        # sizes one state took 70 CPU seconds under the sanitizers, near the
        # time-out, and the larger squares test nothing the smaller do not.
        self.rev_options = []
        if "--states" in words[:-1]:
            self.rev_options = ["--states", words[words.index("--states") + 1].split(",")[0],
                                "--sizes", "0,1"]
        self.tree = load(self.text)
        # Files the scene names (DFN tables, block files, ...) that exist next
        # to it: copied into each case folder so relative paths keep working.
        self.companions = sorted({p for p in self._strings(self.tree)
                                  if (path.parent / p).is_file() and p != path.name})

    def _strings(self, node):
        if isinstance(node, dict):
            for v in node.values():
                yield from self._strings(v)
        elif isinstance(node, list):
            for v in node:
                yield from self._strings(v)
        elif isinstance(node, str) and re.search(r"\.(ya?ml|csv|txt|dat|json|h5)$", node):
            yield node


# ---------------------------------------------------------------------------
# Structure mutations (on the parsed tree)


def walk(node, path=()):
    """(parent, key, path) of every node below `node` (down to 40 levels)."""
    if len(path) > 40:
        return
    if isinstance(node, dict):
        for k, v in node.items():
            yield node, k, path + (k,)
            yield from walk(v, path + (k,))
    elif isinstance(node, list) and not isinstance(node, Pairs):  # Pairs: a leaf
        for i, v in enumerate(node):
            yield node, i, path + (i,)
            yield from walk(v, path + (i,))


# The largest list or polygon a mutation makes (--max-size; lines up to 20x
# longer). The same seed and case give the same scene only with the same value.
MAX_SIZE = [100000]


def up_to(options, limit):
    return [n for n in options if n <= limit] or [options[0]]


def is_point(v):
    return (isinstance(v, list) and len(v) == 2
            and all(isinstance(c, (int, float)) and not isinstance(c, bool) for c in v))


def is_point_list(v):
    return isinstance(v, list) and len(v) >= 2 and all(is_point(p) for p in v)


HUGE_NUMBERS = [1e300, -1e300, 1.7976931348623157e308, 5e-324, -5e-324, 1e-300, 0, 0.0, -0.0,
                -1, 2**31, 2**31 - 1, -2**31 - 1, 2**63, 2**64, 10**30, -10**30, 1e15, 1e9,
                123456789012345678901234567890, float("nan"), float("inf"), float("-inf")]
HUGE_NUMBER_TEXT = ["1e300", "-1e300", "1e309", "-1e309", "1e-320", "0", "-0", "-1", "nan",
                    "inf", "1e18", "99999999999999999999", "0x10", "1_000", "+5", "--5", "5.",
                    ".5", "1e", "e5", "1.2.3", "1e99999"]
UNITS = ["GPa", "MPa", "Pa", "kg/m^3", "m", "mm", "um", "s", "ms", "deg", "rad", "N", "N/m",
         "m/s", "m/s^2", "1/m", "1/m^2", "m^2/s", "Pa*s", "GPa/m", "K", "", "GPA", "m^999",
         "m^-99999", "kg*m/s^2/m^2", "/", "^", "m^", "deg/s", "µm", "\u00b5", "m/"]
WRONG_VALUES = [{}, [], {"a": 1}, [1, 2, 3], [[1, 2], [3, 4]], "abc", "", " ", True, False, None,
                "\u00e4\u20ac\U0001F600", [[[[[]]]]], {"": None}, 2.5, -3, "null", "~",
                "[1, 2", "{a: 1", "x" * 300, 0]
KEY_NOISE = ["x", "_", "0", "name", "type", "~", "\u00e4", "a b", "", "blocks", "physics"]


def mutate_number_string(rng, s):
    m = re.match(r"^\s*([-+0-9.eE]+)\s*(.*)$", s)
    if not m:
        return rng.choice(HUGE_NUMBER_TEXT) + " " + rng.choice(UNITS)
    number, unit = m.groups()
    r = rng.random()
    if r < 0.5:
        return rng.choice(HUGE_NUMBER_TEXT) + (" " + unit if unit else "")
    if r < 0.8:
        return number + " " + rng.choice(UNITS)
    return rng.choice(HUGE_NUMBER_TEXT) + rng.choice(["", " "]) + rng.choice(UNITS)


def huge_value(rng, v):
    if isinstance(v, str):
        return mutate_number_string(rng, v)
    if isinstance(v, bool):
        return rng.choice(WRONG_VALUES)
    if isinstance(v, (int, float)):
        r = rng.random()
        if r < 0.6:
            return rng.choice(HUGE_NUMBERS)
        if r < 0.8:
            return v * rng.choice([-1, 10, 1000, 1e6, 1e-6, 1e12, 1e-12, 1e100, 0.5, 2])
        return v + rng.choice([-1, 1, 0.5, -0.5, 1e-9])
    if isinstance(v, list) and v and not isinstance(v, Pairs):
        return [huge_value(rng, x) if rng.random() < 0.5 else x for x in v]
    return rng.choice(HUGE_NUMBERS)


def polygon(rng, n, kind):
    cx, cy, r = rng.choice([(0, 0, 1), (5, 5, 5), (20, 12, 10), (1e6, 1e6, 1e-3), (0, 0, 1e9)])
    pts = []
    for i in range(n):
        a = 2 * math.pi * i / n
        rr = r
        if kind == "star":
            rr = r * (1 if i % 2 else 0.3)
            a = 2 * math.pi * ((i * (n // 2 - 1)) % n) / n if n > 4 else a
        elif kind == "jagged":
            rr = r * (0.5 + rng.random())
        pts.append([round(cx + rr * math.cos(a), 9), round(cy + rr * math.sin(a), 9)])
    if kind == "degenerate":
        pts = [[0, 0], [1, 1], [2, 2]] + [[3, 3]] * max(0, n - 3)
    elif kind == "repeated":
        pts = pts[: max(3, n // 2)] + pts[: max(3, n // 2)]
    elif kind == "bowtie":
        pts = [[0, 0], [1, 1], [1, 0], [0, 1]]
    elif kind == "tiny":
        pts = [[0, 0], [1e-15, 0], [0, 1e-15]]
    return pts


def pick(rng, entries, pred=lambda parent, key, path: True):
    candidates = [e for e in entries if pred(*e)]
    return rng.choice(candidates) if candidates else None


def set_at(parent, key, value):
    parent[key] = value


def structure_mutation(rng, tree):
    """Mutates `tree` in place (or returns a new root); returns (root, description)."""
    op = rng.choice(["documented_key"] * 5 + ["tweak_number"] * 3 +
                    ["delete", "delete", "duplicate_item", "duplicate_key", "huge_value",
                     "huge_value", "huge_value", "wrong_type", "wrong_type", "rename_key",
                     "unknown_key", "huge_list", "huge_polygon", "polygon", "swap",
                     "deep_nesting", "empty_root_value", "drop_section"])
    if op == "documented_key":
        return tree, add_documented_key(rng, tree)
    if op == "tweak_number":
        return tree, tweak_number(rng, tree)
    entries = list(walk(tree))
    path_text = lambda path: ".".join(str(p) for p in path)
    if op == "delete":
        e = pick(rng, entries)
        if e:
            parent, key, path = e
            del parent[key]
            return tree, f"delete {path_text(path)}"
    elif op == "duplicate_item":
        e = pick(rng, entries, lambda p, k, path: isinstance(p, list))
        if e:
            parent, key, path = e
            parent.insert(key, copy.deepcopy(parent[key]))
            return tree, f"duplicate item {path_text(path)}"
    elif op == "duplicate_key":
        e = pick(rng, entries, lambda p, k, path: isinstance(p, dict) and not isinstance(p, Pairs))
        if e:
            parent, key, path = e
            pairs = Pairs(parent.items())
            value = parent[key] if rng.random() < 0.5 else huge_value(rng, parent[key])
            pairs.insert(rng.randrange(len(pairs) + 1), (key, copy.deepcopy(value)))
            # Replace the map by the pairs in its own parent.
            if len(path) == 1:
                return pairs, f"duplicate key {path_text(path)}"
            for pp, pk, ppath in walk(tree):
                if ppath == path[:-1]:
                    pp[pk] = pairs
                    return tree, f"duplicate key {path_text(path)}"
    elif op == "huge_value":
        e = pick(rng, entries, lambda p, k, path: not isinstance(p[k], (dict, Pairs)))
        if e:
            parent, key, path = e
            old = parent[key]
            parent[key] = huge_value(rng, old)
            return tree, f"value {path_text(path)}: {short(old)} -> {short(parent[key])}"
    elif op == "wrong_type":
        e = pick(rng, entries)
        if e:
            parent, key, path = e
            parent[key] = copy.deepcopy(rng.choice(WRONG_VALUES))
            return tree, f"wrong type {path_text(path)} -> {short(parent[key])}"
    elif op == "rename_key":
        e = pick(rng, entries, lambda p, k, path: isinstance(p, dict) and isinstance(k, str))
        if e:
            parent, key, path = e
            items = list(parent.items())
            new = rng.choice([key[:-1], key + "s", key.upper(), key[1:] + key[0],
                              rng.choice(KEY_NOISE), key + "\u00e4"]) or "_"
            parent.clear()
            for k, v in items:
                parent[new if k == key else k] = v
            return tree, f"rename key {path_text(path)} -> {new}"
    elif op == "unknown_key":
        e = pick(rng, entries, lambda p, k, path: isinstance(p[k], dict))
        target, where = (tree, "(root)") if e is None or rng.random() < 0.3 else (
            e[0][e[1]], path_text(e[2]))
        if isinstance(target, dict):
            key = rng.choice(KEY_NOISE) or "unknown"
            target[key] = copy.deepcopy(rng.choice(WRONG_VALUES))
            return tree, f"unknown key {where}.{key}"
    elif op == "huge_list":
        e = pick(rng, entries, lambda p, k, path: isinstance(p[k], list) and p[k]
                 and not isinstance(p[k], Pairs))
        if e:
            parent, key, path = e
            n = rng.choice(up_to((10, 100, 1000, 10000, 100000), MAX_SIZE[0]))
            items = parent[key]
            parent[key] = [copy.deepcopy(items[i % len(items)]) for i in range(n)]
            return tree, f"huge list {path_text(path)} x{n}"
    elif op in ("huge_polygon", "polygon"):
        e = pick(rng, entries, lambda p, k, path: is_point_list(p[k]))
        if e:
            parent, key, path = e
            if op == "huge_polygon":
                n = rng.choice(up_to((1000, 10000, 100000), MAX_SIZE[0]))
                kind = rng.choice(["circle", "jagged", "star"])
            else:
                n = rng.choice([3, 4, 5, 7, 50])
                kind = rng.choice(["circle", "star", "degenerate", "repeated", "bowtie", "tiny",
                                   "jagged"])
            parent[key] = polygon(rng, n, kind)
            return tree, f"polygon {path_text(path)}: {kind} of {len(parent[key])} vertices"
    elif op == "swap":
        a = pick(rng, entries)
        b = pick(rng, entries)
        if a and b and a[2] != b[2] and a[2][: len(b[2])] != b[2] and b[2][: len(a[2])] != a[2]:
            va, vb = copy.deepcopy(a[0][a[1]]), copy.deepcopy(b[0][b[1]])
            a[0][a[1]], b[0][b[1]] = vb, va
            return tree, f"swap {path_text(a[2])} <-> {path_text(b[2])}"
    elif op == "deep_nesting":
        e = pick(rng, entries)
        if e:
            parent, key, path = e
            depth = rng.choice([10, 50, 200])  # deeper: text mutation
            v = parent[key]
            for _ in range(depth):
                v = [v] if rng.random() < 0.5 else {"a": v}
            parent[key] = v
            return tree, f"deep nesting {path_text(path)} x{depth}"
    elif op in ("empty_root_value", "drop_section"):
        if isinstance(tree, dict) and tree:
            key = rng.choice(list(tree))
            if op == "empty_root_value":
                tree[key] = None
                return tree, f"empty value {key}"
            del tree[key]
            return tree, f"delete {key}"
    return tree, None


def short(v, n=40):
    s = repr(v)
    return s if len(s) <= n else s[:n] + "..."

# ---------------------------------------------------------------------------
# The documented keys (docs/scene-reference.md, docs/flow.md's REV study
# table): `| \`key.path\` | type | ...` rows give each key, its type and, in
# back-ticks, the names it accepts. "Add a documented key" sets one of them to
# a value of its type, so that scenes also vary in the keys the configs leave
# at their defaults (valid values reach the run, not only the reader).


def documented_keys(repo):
    keys = []
    for doc in ("docs/scene-reference.md", "docs/flow.md"):
        path = repo / doc
        if not path.is_file():
            continue
        for line in path.read_text(errors="replace").splitlines():
            m = re.match(r"^\| `([a-z_0-9.\[\]]+)` \| ([^|]*) \|(.*)$", line)
            if not m:
                continue
            key, kind, rest = m.groups()
            options = [o for o in re.findall(r"`([a-z_][a-z_0-9]*)`", kind + rest)
                       if o not in key.replace("[]", "").split(".")]
            keys.append((key, kind.lower(), options))
    return keys


DOC_KEYS = []


def random_magnitude(rng):
    v = 10 ** rng.uniform(-9, 12)
    v = float(f"{v:.3g}")
    return -v if rng.random() < 0.15 else rng.choice([v, v, 0, 1, 0.5])


def value_for(rng, kind, options, tree):
    if options and ("name" in kind or "string" in kind or "or" in kind) and rng.random() < 0.8:
        return rng.choice(options)
    if "boolean" in kind:
        return rng.choice([True, False])
    if "integer" in kind:
        return rng.choice([0, 1, 2, 3, 5, 12, 100, 1000, 10**6, -1])
    if "list of pairs" in kind or "[t, factor]" in kind:
        return rng.choice([[[0, 0], [1, 1]], [[0, 1]], [[0, 1], [0, 2]], [[1, 0], [0, 1]],
                           [[0, 0], [1e-9, 1], [1e9, -1]]])
    if "[sxx, syy, sxy]" in kind or "[vx, vy, omega]" in kind:
        return [random_magnitude(rng) for _ in range(3)]
    if "two points" in kind:
        return [[0, 0], [rng.choice([1, 10, 40, 1e-6, 1e6]), rng.choice([1, 10, 25, 0])]]
    if "point" in kind or "vector" in kind:
        return [round(rng.uniform(-5, 45), 3), round(rng.uniform(-5, 30), 3)]
    if kind.startswith("map"):
        return {}
    if kind.startswith("list"):
        return []
    if "angle" in kind:
        return rng.choice([0, 1, 30, 45, 89.9, 90, 180, -30, 720])
    if "name" in kind or "string" in kind:
        names = [p[k] for p, k, path in walk(tree) if k == "name" and isinstance(p[k], str)]
        return rng.choice(["none", "left", "top", "x", "block0", "rock1"] + names)
    return random_magnitude(rng)


def add_documented_key(rng, tree):
    if not DOC_KEYS or not isinstance(tree, dict):
        return None
    key, kind, options = rng.choice(DOC_KEYS)
    node = tree
    parts = key.split(".")
    for part in parts[:-1]:
        is_list = part.endswith("[]")
        name = part[:-2] if is_list else part
        if not isinstance(node, dict):
            return None
        if name not in node or node[name] is None:
            if is_list:
                return None
            node[name] = {}
        node = node[name]
        if is_list:
            if not isinstance(node, list) or not node:
                return None
            node = rng.choice(node)
    last = parts[-1]
    if last.endswith("[]") or not isinstance(node, dict):
        return None
    node[last] = value_for(rng, kind, options, tree)
    return f"documented key {key} = {short(node[last])}"


NUMBER_WITH_UNIT = re.compile(r"^(-?[0-9.]+(?:e-?[0-9]+)?)(\s*\S*)$")


def times(v, factor):
    """A YAML number, or the number of 'NUMBER UNIT' (its unit kept), times
    `factor`; None when it is neither."""
    if isinstance(v, str):
        m = NUMBER_WITH_UNIT.match(v)
        try:
            return f"{float(m.group(1)) * factor:.6g}{m.group(2)}"
        except (AttributeError, ValueError):
            return None
    return type(v)(v * factor) if isinstance(v, int) and factor == int(factor) else v * factor


def tweak_number(rng, tree):
    """A number (or the number of 'NUMBER UNIT') times a modest factor."""
    entries = [e for e in walk(tree)
               if (isinstance(e[0][e[1]], (int, float)) and not isinstance(e[0][e[1]], bool))
               or (isinstance(e[0][e[1]], str) and NUMBER_WITH_UNIT.match(e[0][e[1]]))]
    if not entries:
        return None
    parent, key, path = rng.choice(entries)
    old = parent[key]
    factor = rng.choice([0.1, 0.5, 0.9, 1.1, 2, 10, 100, -1, 0])
    new = times(old, factor)
    if new is None:
        return None
    parent[key] = new
    return f"number {'.'.join(map(str, path))}: {short(old)} -> {short(parent[key])}"


# ---------------------------------------------------------------------------
# Targeted mutations (issue 35): the values that once went wrong without a
# word, in every scene that has them.
#
#   not_positive  a number of the thermal, continuum or flow section (a time
#                 step, a mesh size, a modulus) made NaN, infinite, zero or
#                 negative: refused at its key, never reported missing
#   mesh          a mesh made 10-10,000 times finer, its max_elements raised
#                 from 100 times finer on:
#                 refused from its estimate or run, never out of memory
#   generator     a rock-mass or REV DFN generator key set to a value of
#                 fuzz_generator_keys.VALUES (lengths 1e-6 .. 1e9 m, ...):
#                 `validate` within the work budget (--validate-seconds,
#                 --validate-mb)
#   petsc         PETSc options that PETSc refuses or misreads: refused at the
#                 key with PETSc's reason

NOT_POSITIVE_SECTIONS = ("thermal", "continuum", "flow")
NOT_POSITIVE_NUMBERS = ["nan", ".nan", "-.nan", ".inf", "-.inf", "0", "-0", "-1", "-1e-300"]
MESH_SIZE_KEYS = ("element_size", "fine_element_size", "source_element_size")
PETSC_OPTIONS = ["-ksp_type nonsense", "-pc_type", "-ksp_rtol -1", "-ksp_max_it 1e99",
                 "-ksp_max_it -5", "--", "x y z", "-ksp_type cg -pc_type gamg", "-pc_type lu",
                 "-ksp_type preonly -pc_type none", "-pc_factor_mat_solver_type nosuch",
                 "-ksp_rtol nan", "-ksp_atol 1e400", "-ksp_monitor", "-options_left",
                 "-pc_type hypre -pc_hypre_type nosuch", "\"unbalanced", "-ksp_gmres_restart 0"]
PETSC_KEYS = (("continuum", "solver"), ("flow", "solver"), ("mechanics", "dda", "solver"))


def made_not_positive(rng, number):
    """`number` (a YAML number or 'NUMBER UNIT') made NaN, infinite, zero or
    negative, keeping its unit."""
    text = rng.choice(NOT_POSITIVE_NUMBERS)
    if isinstance(number, str):
        unit = number.strip().split(None, 1)[1:] or [""]
        return f"{text} {unit[0]}".strip()
    return load(text)


def targeted_mutation(rng, tree):
    """One targeted mutation of `tree` in place: (description, kind) or (None, None)."""
    if not isinstance(tree, dict):
        return None, None
    kind = rng.choice(["not_positive", "not_positive", "mesh", "generator", "generator", "petsc"])
    path_text = lambda path: ".".join(str(p) for p in path)
    if kind == "not_positive":
        entries = [e for e in walk(tree) if e[2][0] in NOT_POSITIVE_SECTIONS
                   and generators.numeric(e[0][e[1]])]
        if entries:
            parent, key, path = rng.choice(entries)
            old = parent[key]
            parent[key] = made_not_positive(rng, old)
            return f"{path_text(path)}: {short(old)} -> {short(parent[key])}", kind
    elif kind == "mesh":
        meshes = [(p[k], path) for p, k, path in walk(tree)
                  if k == "mesh" and isinstance(p[k], dict)]
        if meshes:
            mesh, path = rng.choice(meshes)
            factor = 10 ** rng.choice([1, 2, 3, 4])
            changed = []
            for k in MESH_SIZE_KEYS:
                finer = times(mesh.get(k), 1 / factor) if generators.numeric(mesh.get(k)) else None
                if finer is not None:
                    mesh[k] = finer
                    changed.append(k)
            if isinstance(mesh.get("divisions"), list):
                mesh["divisions"] = [d * factor if isinstance(d, int) else d
                                     for d in mesh["divisions"]]
                changed.append("divisions")
            if changed:
                # max_elements is raised only where the memory budget must
                # refuse (10,000 times the triangles and more): 100 times the
                # triangles within the budget is real work the user asked for
                # by raising the limit (a thermal mesh of millions of
                # triangles meshes for minutes), not a hang.
                if rng.random() < 0.7 and factor >= 100:
                    mesh["max_elements"] = rng.choice([1e7, 1e8, 1e9])
                    changed.append(f"max_elements {mesh['max_elements']:g}")
                return f"{path_text(path)} {factor}x finer ({', '.join(changed)})", kind
    elif kind == "generator":
        keys = generators.generator_keys(tree)
        if keys:
            path, key_kind = rng.choice(keys)
            value = rng.choice(generators.VALUES[key_kind])
            try:
                generators.apply(tree, path, key_kind, value)
            except (KeyError, IndexError, TypeError, ValueError, AttributeError):
                return None, None
            return f"generator {path_text(path)} = {generators.text_of(key_kind, value)}", kind
    elif kind == "petsc":
        solvers = []
        for keys in PETSC_KEYS:
            node = tree
            for k in keys[:-1]:
                node = node.get(k) if isinstance(node, dict) else None
            if isinstance(node, dict):
                solvers.append((node, keys))
        if solvers:
            parent, keys = rng.choice(solvers)
            solver = parent.get(keys[-1])
            if not isinstance(solver, dict):
                solver = parent[keys[-1]] = {}
            if rng.random() < 0.7:
                solver["type"] = "petsc"
            solver["petsc_options"] = rng.choice(PETSC_OPTIONS)
            return f"{path_text(keys)}: type {solver.get('type')}, petsc_options " \
                   f"{solver['petsc_options']!r}", kind
    return None, None


# ---------------------------------------------------------------------------
# Text mutations (on the bytes)

STRAY = [b"\x00", b"\xff", b"\xfe", b"\x80", b"\xc3", b"\xe2\x80", b"\xed\xa0\x80", b"\t", b"\r",
         b"\x1b", b"\x7f", b"\x0b", b"\x0c", b'"', b"'", b"{", b"}", b"[", b"]", b":", b": ",
         b"&", b"*", b"!", b"%", b"|", b">", b"#", b"-", b"- ", b"?", b"@", b"`", b",", b"\\",
         b"\n", b"  ", b"!!binary ", b"!!python/object ", b"<<: ", b"&a ", b"*a", b"---\n",
         b"...\n", b"%YAML 1.2\n", b"\xef\xbb\xbf"]


def text_mutation(rng, data):
    op = rng.choice(["truncate", "stray", "stray", "overwrite", "delete_span", "long_line",
                     "long_line", "dup_line", "del_line", "swap_lines", "indent", "bom", "crlf",
                     "deep_brackets", "alias_bomb", "long_value"])
    lines = data.split(b"\n")
    if op == "truncate":
        pos = rng.randrange(len(data) + 1)
        return data[:pos], f"truncate at byte {pos}"
    if op == "stray":
        pos = rng.randrange(len(data) + 1)
        ins = b"".join(rng.choice(STRAY) for _ in range(rng.randint(1, 5)))
        return data[:pos] + ins + data[pos:], f"insert {ins!r} at byte {pos}"
    if op == "overwrite":
        pos = rng.randrange(max(1, len(data)))
        b = bytes([rng.randrange(256)])
        return data[:pos] + b + data[pos + 1:], f"byte {pos} -> {b!r}"
    if op == "delete_span":
        pos = rng.randrange(max(1, len(data)))
        n = rng.choice([1, 2, 5, 20, 200])
        return data[:pos] + data[pos + n:], f"delete {n} bytes at {pos}"
    if op == "long_line":
        i = rng.randrange(len(lines) + 1)
        n = rng.choice(up_to((10**4, 10**5, 10**6, 2 * 10**6), 20 * MAX_SIZE[0]))
        kind = rng.choice(["comment", "key", "scalar", "flow_list", "number"])
        line = {
            "comment": lambda: b"# " + b"x" * n,
            "key": lambda: b"k" * n + b": 1",
            "scalar": lambda: b"name: " + b"y" * n,
            "flow_list": lambda: b"physics: [" + b"mechanics, " * (n // 11) + b"]",
            "number": lambda: b"seed: " + b"9" * n,
        }[kind]()
        lines.insert(i, line)
        return b"\n".join(lines), f"long line ({kind}, {n} bytes) at line {i + 1}"
    if op == "long_value":
        # Lengthen the value of an existing `key: value` line.
        idx = [i for i, l in enumerate(lines) if re.match(rb"^\s*-?\s*\w+: \S", l)]
        if idx:
            i = rng.choice(idx)
            n = rng.choice(up_to((10**3, 10**5, 10**6), 10 * MAX_SIZE[0]))
            lines[i] = lines[i] + rng.choice([b"0", b"9", b" ", b"x", b"e"]) * n
            return b"\n".join(lines), f"long value ({n} bytes) at line {i + 1}"
    if op == "dup_line":
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        return b"\n".join(lines), f"duplicate line {i + 1}"
    if op == "del_line":
        i = rng.randrange(len(lines))
        del lines[i]
        return b"\n".join(lines), f"delete line {i + 1}"
    if op == "swap_lines":
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        return b"\n".join(lines), f"swap lines {i + 1} and {j + 1}"
    if op == "indent":
        i = rng.randrange(len(lines))
        d = rng.choice([-4, -2, -1, 1, 2, 4])
        lines[i] = b" " * d + lines[i] if d > 0 else lines[i][-d:]
        return b"\n".join(lines), f"indent line {i + 1} by {d}"
    if op == "bom":
        return b"\xef\xbb\xbf" + data, "byte-order mark"
    if op == "crlf":
        return data.replace(b"\n", rng.choice([b"\r\n", b"\r"])), "CR line ends"
    if op == "deep_brackets":
        n = rng.choice(up_to((100, 1000, 10000, 100000), MAX_SIZE[0]))
        idx = [i for i, l in enumerate(lines) if re.match(rb"^\s*\w+: \S", l)]
        if idx:
            i = rng.choice(idx)
            key = lines[i].split(b":")[0]
            lines[i] = key + b": " + rng.choice([b"[", b"{a: "]) * n
            return b"\n".join(lines), f"{n} nested brackets at line {i + 1}"
    if op == "alias_bomb":
        idx = [i for i, l in enumerate(lines) if re.match(rb"^\w+: \S", l)]
        if idx:
            i = rng.choice(idx)
            key = lines[i].split(b":")[0]
            bomb = [b"x0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]"]
            depth = rng.choice([3, 6, 9])
            for d in range(1, depth + 1):
                bomb.append(b"x%d: &a%d [" % (d, d) + b", ".join([b"*a%d" % (d - 1)] * 10) + b"]")
            lines[i] = key + b": *a%d" % depth
            return b"\n".join(bomb + lines), f"alias bomb (10^{depth + 1}) as {key.decode()}"
    return data, None


# ---------------------------------------------------------------------------
# A case


# A share of the cases of a `fissure run` scene restart from a checkpoint of
# it that they corrupt first (or, one in ten, leave intact):
#
#   flip      1 to 16 bytes changed (XOR with a non-zero byte), at any offset
#             or in the integrity record (the first 512 bytes)
#   scramble  up to 4 kB of random bytes over the file's own
#   zero      512 B to 4 kB of zeros
#   truncate  the file cut short, anywhere
#   extend    bytes appended
#   foreign   another scene's checkpoint in its place
#
# The restart must be refused whole (exit 1, "the restart is refused"),
# leaving every file of the output folder as it was; an intact checkpoint
# must continue.
CHECKPOINT_SHARE = [0.06]  # --checkpoint-share
CORRUPTIONS = ["intact", "flip", "flip", "flip", "scramble", "zero", "truncate", "extend",
               "foreign"]


def checkpoint_corruption(rng, sources):
    how = rng.choice(CORRUPTIONS)
    c = {"how": how, "seed": rng.randrange(2**32)}
    if how == "flip":
        c["bytes"] = rng.choice([1, 1, 2, 16])
        c["where"] = "record" if rng.random() < 0.2 else "anywhere"
    elif how in ("scramble", "zero"):
        c["bytes"] = rng.choice([512, 1024, 4096]) if how == "zero" else rng.randint(1, 4096)
    elif how == "extend":
        c["bytes"] = rng.choice([1, 8, 4096])
    elif how == "foreign":
        c["scene"] = rng.choice([s.name for s in sources if s.mode == "run"])
    return c


def make_case(sources, seed, index):
    """Case `index`: its source scene, the scene's bytes, the mutations'
    descriptions, the targeted kinds among them and, for a checkpoint case,
    the checkpoint's corruption."""
    rng = random.Random(f"fissure-fuzz-{seed}-{index}")
    source = sources[index % len(sources)]
    case = {"source": source, "ops": [], "kinds": set(), "checkpoint": None}
    ops = case["ops"]
    if source.mode == "run" and rng.random() < CHECKPOINT_SHARE[0]:
        case["checkpoint"] = checkpoint_corruption(rng, sources)
        case["data"] = source.text
        ops.append("checkpoint: " + ", ".join(f"{k} {v}" for k, v in
                                              case["checkpoint"].items() if k != "seed"))
        return case
    n = rng.choice([1, 1, 1, 2, 2, 3])
    if rng.random() < 0.6:
        tree = copy.deepcopy(source.tree)
        for _ in range(n * 3):  # some operations find nothing to act on
            if rng.random() < 0.25:
                d, kind = targeted_mutation(rng, tree)
                if d:
                    case["kinds"].add(kind)
                    ops.append(f"{kind}: {d}")
            else:
                tree, d = structure_mutation(rng, tree)
                if d:
                    ops.append("structure: " + d)
            if len(ops) == n:
                break
        data = dump(tree)
        if rng.random() < 0.15:  # and sometimes a text mutation on top
            data, d = text_mutation(rng, data)
            if d:
                ops.append("text: " + d)
    else:
        data = source.text
        for _ in range(n * 3):
            data, d = text_mutation(rng, data)
            if d:
                ops.append("text: " + d)
            if len(ops) == n:
                break
    case["data"] = data
    return case


SANITIZER_OOM = re.compile(r"hard rss limit exhausted|allocation-size-too-big|"
                           r"requested allocation size .* exceeds|out of memory: allocator")
SANITIZER_REPORT = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:")


def run_command(args, cwd, timeout, memory_mb):
    """run_once, and under the sanitizers once more when the first run's only
    report is a leak: LeakSanitizer then reports with the fast unwinder's
    stacks, which stop at the first frame of an uninstrumented library and so
    miss the suppressions (tests/sanitizers/lsan.supp: Open MPI's memory at
    exit, after MPI_Finalize has unloaded its plugins; a scene that picks the
    PETSc back end). The second run records full stacks
    (fast_unwind_on_malloc=0, too slow for every run): a leak in Fissure's
    code is still reported, Open MPI's is suppressed."""
    r = run_once(args, cwd, timeout, memory_mb)
    if fuzz_common.SANITIZED[0] and leak_only(r["stderr"]):
        r = run_once(args, cwd, timeout, memory_mb, ["fast_unwind_on_malloc=0"])
    return r


def leak_only(stderr):
    return ("ERROR: LeakSanitizer" in stderr and "ERROR: AddressSanitizer" not in stderr
            and "runtime error:" not in stderr)


def run_once(args, cwd, timeout, memory_mb, asan_options=()):
    """Runs one command with `timeout` CPU seconds (and 5x that plus 30 s of
    wall time, for a process that waits instead of computing); returns
    fuzz_common.run_measured's record (rc, output, CPU and wall seconds, peak
    resident memory, timed_out)."""
    env = {}
    if fuzz_common.SANITIZED[0] and memory_mb > 0:
        asan_options = [f"hard_rss_limit_mb={memory_mb}", f"max_allocation_size_mb={memory_mb}",
                        "allocator_may_return_null=1", *asan_options]
    if asan_options:
        env["ASAN_OPTIONS"] = ":".join(
            filter(None, [os.environ.get("ASAN_OPTIONS", ""), *asan_options]))
    return run_measured(args, cwd, timeout, 5 * timeout + 30, memory_mb, env)


RUNTIME_PATTERN = re.compile(
    r"\bsteps?\b|\bt = |\btime\b|iteration|^(error: )?(mechanics|flow|dda)\b", re.I)


def signal_name(rc):
    try:
        return signal.Signals(-rc).name
    except ValueError:
        return f"signal {-rc}"


def classify_process(r, stage, scene_name):
    """(class, message) from one process, or None when it succeeded."""
    if fuzz_common.SANITIZED[0] and SANITIZER_OOM.search(r["stderr"]):
        return "OOM", f"{stage}: the sanitizer's memory limit; {first_error(r)}"
    if fuzz_common.SANITIZED[0] and SANITIZER_REPORT.search(r["stderr"]):
        report = next(l for l in r["stderr"].splitlines() if SANITIZER_REPORT.search(l))
        return "CRASH", f"{stage}: sanitizer report: {report.strip()[:300]}"
    if r["timed_out"]:
        return "HANG", (f"{stage}: no exit after {r['cpu_seconds']:.0f} CPU seconds "
                        f"({r['seconds']:.0f} s wall)")
    if r["rc"] < 0:
        if OOM_PATTERN.search(r["stderr"]):
            return "OOM", f"{stage}: {signal_name(r['rc'])} after {first_error(r)}"
        return "CRASH", f"{stage}: {signal_name(r['rc'])}; {first_error(r)}"
    if r["rc"] == 0:
        return None
    reason = "\n".join(l for l in r["stdout"].splitlines() if l.strip().startswith("reason:"))
    if OOM_PATTERN.search(r["stderr"] + reason):
        return "OOM", f"{stage}: {first_error(r)}"
    return "ERROR", first_error(r)


def first_error(r):
    lines = error_lines(r["stderr"])
    reason = [l.strip() for l in r["stdout"].splitlines() if l.strip().startswith("reason:")]
    text = (lines[0] if lines and lines[0] != "error: invalid scene" else
            lines[1] if len(lines) > 1 else lines[0] if lines else "")
    if reason:
        text = (text + " | " if text else "") + reason[0]
    return text[:300] or f"(exit {r['rc']}, no message)"


def check_outputs(outdir):
    """Non-finite values in the run's output: a list of findings."""
    findings, notes = [], []
    csv_path = outdir / "monitors.csv"
    if csv_path.is_file():
        with open(csv_path, newline="", errors="replace") as f:
            rows = list(csv.reader(f))
        header = rows[0] if rows else []
        for n, row in enumerate(rows[1:], start=2):
            for c, cell in enumerate(row):
                v = cell.strip().lower()
                if v in ("nan", "-nan", "inf", "-inf", "+inf", "infinity", "-infinity"):
                    column = header[c] if c < len(header) else f"column {c}"
                    findings.append(("monitors.csv", column, n, cell))
    summary = outdir / "summary.json"
    if summary.is_file():
        text = summary.read_text(errors="replace")
        if re.search(r"\bNaN\b|\bInfinity\b", text):
            findings.append(("summary.json", "NaN/Infinity token", 0, ""))
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as e:
            findings.append(("summary.json", f"invalid JSON ({e})", 0, ""))
            doc = {}
        for section in ("monitors", "energy"):
            for key, path in null_leaves(doc.get(section), section):
                findings.append(("summary.json", path, 0, "null"))
    h5 = outdir / "results.h5"
    if h5.is_file():
        if not HAVE_H5PY:
            notes.append("results.h5 not checked (no h5py)")
        else:
            try:
                with h5py.File(h5, "r") as f:
                    bad = []

                    def visit(name, obj):
                        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                            a = obj[()]
                            if not numpy.all(numpy.isfinite(a)):
                                bad.append(name)
                    f.visititems(visit)
                    for name in bad[:5]:
                        findings.append(("results.h5", name, 0, "non-finite"))
            except Exception as e:  # a damaged file is its own finding
                findings.append(("results.h5", f"unreadable ({e})", 0, ""))
    return findings, notes


def not_positive(x):
    try:
        return float(x) <= 0
    except (TypeError, ValueError):
        return False


def check_rev_outputs(outdir):
    """Non-finite values in a REV study's tables and rev.json. The CV of a size
    whose mean k is not positive (no connected realization, or a fitted
    k_min <= 0) is inf (null in rev.json) by design (docs/flow.md); anything
    else non-finite is a finding."""
    findings = []
    non_finite = {"nan", "-nan", "inf", "-inf", "+inf", "infinity", "-infinity"}
    for f in sorted(outdir.glob("*.csv")):
        with open(f, newline="", errors="replace") as fh:
            rows = list(csv.reader(fh))
        header = rows[0] if rows else []
        for n, row in enumerate(rows[1:], start=2):
            cells = dict(zip(header, row))
            for column, cell in cells.items():
                if cell.strip().lower() not in non_finite:
                    continue
                mean = cells.get("mean_k" + column[-3:], "")
                if (f.name == "sizes.csv" and column in ("cv_kmax", "cv_kmin")
                        and "inf" in cell.lower()
                        and (cells.get("samples") == "0" or not_positive(mean))):
                    continue
                findings.append(f"{f.name}: row {n} {column} = {cell}")
    rev = outdir / "rev.json"
    if rev.is_file():
        text = rev.read_text(errors="replace")
        if re.search(r"\bNaN\b|\bInfinity\b", text):
            findings.append("rev.json: NaN/Infinity token")
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as e:
            return findings + [f"rev.json: invalid JSON ({e})"]
        for path, _ in null_leaves(doc, "rev"):
            m = re.match(r"^rev\.sizes\[(\d+)\]\.(k_m(ax|in))\.cv$", path)
            if m:
                size = doc["sizes"][int(m.group(1))]
                if size.get("samples") == 0 or not_positive(size[m.group(2)].get("mean")):
                    continue
            if path == "rev.rev_size":
                continue
            findings.append(f"rev.json: {path} = null")
    return findings


def null_leaves(node, path):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from null_leaves(v, f"{path}.{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from null_leaves(v, f"{path}[{i}]")
    elif node is None:
        yield path, path


def off_network_monitors(stderr):
    """Monitors whose pressure is documented as nan: not on the fracture network."""
    return set(re.findall(r"monitor '([^']*)' at .* is not on the fracture network", stderr))


def allowed_nan(finding, off_network):
    """The documented nan: `p` of a monitor off the fracture network (docs/output.md)."""
    where, column = finding[0], finding[1]
    if where == "monitors.csv":
        m = re.match(r"^(.*)\.p$", column)
        return bool(m and m.group(1) in off_network)
    if where == "summary.json":
        m = re.match(r"^monitors\.(.*)\.p$", column)
        return bool(m and m.group(1) in off_network)
    return False


def nan_in_output(outdir, stderr):
    """(the first non-finite value a run wrote beyond the documented ones, as
    text, or None; the checks' notes)."""
    findings, notes = check_outputs(outdir)
    off = off_network_monitors(stderr)
    findings = [f for f in findings if not allowed_nan(f, off)]
    if not findings:
        return None, notes
    f = findings[0]
    return (f"{f[0]}: {f[1]}" + (f" row {f[2]}" if f[2] else "") + f" = {f[3]}" +
            (f" (+{len(findings) - 1} more)" if len(findings) > 1 else "")), notes


# More error lines than this are a flood (Diagnostics shows at most 100
# problems and summarizes the rest: core/scene/diagnostics.h).
FLOOD_LINES = 150
MISSING = re.compile(r"^(.+?):\d+:\d+: (\S+): key is missing")


def lookup(tree, path):
    """The value at `path` ('thermal.time_step', 'blocks[3].material') of
    the parsed scene, or None."""
    node = tree
    for token in re.findall(r"\[(\d+)\]|([^.\[\]]+)", path):
        index, key = token
        if index and isinstance(node, list) and not isinstance(node, Pairs):
            node = node[int(index)] if int(index) < len(node) else None
        elif key and isinstance(node, dict):
            node = node.get(key)
        else:
            return None
        if node is None:
            return None
    return node


def said_missing(stderr, scene_name, data):
    """An error line that calls a key missing which the scene has (with a
    value: an empty one is missing)."""
    lines = [l for l in error_lines(stderr) if MISSING.match(l)]
    if not lines:
        return None
    # PyYAML's C loader recurses per nesting level: 100,000 open brackets
    # overflow the worker's stack (a segfault that stalls the pool).
    if re.search(rb"[\[{]{200}", data if isinstance(data, bytes) else data.encode()):
        return None
    try:
        tree = load(data)
    except Exception:  # a text mutation PyYAML does not read either
        return None
    # A key given twice: Fissure reads the first (and reports the second),
    # PyYAML keeps the last; what is missing in the first may be in the last.
    twice = set(re.findall(r"found a second '([^']*)'", stderr))
    for line in lines:
        m = MISSING.match(line)
        if (m and m.group(1) == scene_name and lookup(tree, m.group(2)) is not None
                and not twice & set(re.split(r"[.\[\]]+", m.group(2)))):
            return line
    return None


def over_budget(args, case, r, stage):
    """A generator case whose `validate` (a REV study's one realization)
    took more than --validate-seconds of CPU or --validate-mb of memory
    (issue 35: work known before it is spent). Not under the sanitizers,
    which are slower and bigger by design."""
    if "generator" not in case["kinds"] or fuzz_common.SANITIZED[0]:
        return None
    if r["cpu_seconds"] > args.validate_seconds or r["rss_mb"] > args.validate_mb:
        return "OVER-BUDGET", (f"{stage}: {r['cpu_seconds']:.1f} CPU s, {r['rss_mb']:.0f} MB "
                               f"(budget {args.validate_seconds:g} s, {args.validate_mb} MB)")
    return None


def write_scene(source, data, folder):
    """The scene's bytes and the files it names, in `folder`."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / source.path.name).write_bytes(data)
    for c in source.companions:
        target = folder / c
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source.path.parent / c, target)


def execute(args, case, case_dir):
    """Writes and runs one case; returns its result dict (without minimisation)."""
    source, data = case["source"], case["data"]
    write_scene(source, data, case_dir)
    scene_name = source.path.name
    result = {"scene": source.name, "file": str(case_dir / scene_name), "processes": []}
    out = case_dir / "out"
    fissure = str(Path(args.fissure).resolve())

    def finish(cls, message, **extra):
        result.update({"class": cls, "message": message}, **extra)
        return result

    if case["checkpoint"]:
        return execute_restart(args, case, case_dir, result, finish)

    def rejected_well(r, stage):
        """The class of a rejection beyond its location: an error flood, a
        key said missing that the scene has; None when it is neither."""
        lines = error_lines(r["stderr"])
        if len(lines) > FLOOD_LINES:
            return "FLOOD", f"{stage}: {len(lines)} lines of errors"
        line = said_missing(r["stderr"], scene_name, data)
        if line:
            return "MISLEADING", f"{stage}: {line[:280]}"
        return None

    if source.mode == "rev":
        cmd = [fissure, "rev", scene_name, "-o", "out", "--realizations", "1", "--no-plots",
               "-j", "1", "-q"] + source.rev_options
        r = run_command(cmd, case_dir, args.timeout, args.memory_mb)
        result["processes"].append(r)
        c = classify_process(r, "rev", scene_name)
        if c is None or c[0] == "ERROR":
            c = over_budget(args, case, r, "rev") or c
        if c is None:
            findings = check_rev_outputs(case_dir / "out")
            if findings:
                return finish("NAN", findings[0])
            return finish("RAN", "")
        if c[0] != "ERROR":
            return finish(*c)
        bad = located(r["stderr"], scene_name)
        if r["rc"] == 1 and not bad:
            return finish(*(rejected_well(r, "rev") or ("REJECTED", c[1])))
        if r["rc"] == 2 and RUNTIME_PATTERN.search(c[1]):
            return finish("RUNTIME-STOP", "rev: " + c[1])
        return finish("UNLOCATED", f"rev exit {r['rc']}: {bad[0] if bad else c[1]}")

    # 1. validate
    r = run_command([fissure, "validate", scene_name], case_dir, args.timeout, args.memory_mb)
    result["processes"].append(r)
    c = classify_process(r, "validate", scene_name)
    if c is None or c[0] == "ERROR":
        c = over_budget(args, case, r, "validate") or c
    if c is not None:
        if c[0] != "ERROR":
            return finish(*c)
        bad = located(r["stderr"], scene_name)
        if r["rc"] == 1 and not bad:
            return finish(*(rejected_well(r, "validate") or ("REJECTED", c[1])))
        return finish("UNLOCATED", f"validate exit {r['rc']}: {bad[0]}")

    # 2. a few steps
    r = run_command([fissure, "run", scene_name, "-o", "out", "--max-steps", str(args.max_steps),
                     "-q", "--no-plots"], case_dir, args.timeout, args.memory_mb)
    result["processes"].append(r)
    c = classify_process(r, "run", scene_name)
    if c is not None and c[0] != "ERROR":
        return finish(*c)
    nan, notes = nan_in_output(out, r["stderr"])
    if notes:
        result["notes"] = notes
    if c is None:
        return finish("NAN", nan) if nan else finish("RAN", "")
    # A scene problem found only by the run: `error: invalid scene`, or a stop
    # whose reason reads "...; expected ..." (the scene messages' form). Located
    # (FILE:LINE:COLUMN somewhere in it), it is VALIDATE-ACCEPTS-RUN-REJECTS;
    # without a location, UNLOCATED.
    lines = error_lines(r["stderr"])
    scene_problem = "error: invalid scene" in lines or "; expected " in c[1]
    if scene_problem:
        if re.search(re.escape(scene_name) + r":\d+:\d+: ", r["stderr"] + r["stdout"]):
            return finish("VALIDATE-ACCEPTS-RUN-REJECTS", c[1])
        return finish("UNLOCATED", f"run rejects the scene without a location: {c[1]}")
    # A run that stopped early (exit 2) says how far it got ("diverged after
    # 12 steps, t = ...") and why; an exception that escaped must name the step,
    # the time or the process itself.
    m = re.search(r": (\w+) after (\d+) steps, t = (\S+) s", r["stdout"])
    if r["rc"] == 2 and (m or RUNTIME_PATTERN.search(c[1])):
        status = f"{m.group(1)} after {m.group(2)} steps" if m else "stopped"
        if nan:
            return finish("NAN", f"run {status}, output holds {nan}: {c[1]}")
        return finish("RUNTIME-STOP", f"run {status}: {c[1]}")
    return finish("UNLOCATED", f"run exit {r['rc']}: {c[1]}")


def base_checkpoint(args, sources, name):
    """The folder (the scene, writing a checkpoint every step, and `out/` of
    its first steps with checkpoint.h5) that the checkpoint cases of scene
    `name` start from; made once per run, whichever worker asks first.
    None when the scene wrote no checkpoint (the reason in `failed.txt`)."""
    source = next(s for s in sources if s.name == name)
    folder = Path(args.out) / "checkpoints" / name
    folder.parent.mkdir(parents=True, exist_ok=True)
    with open(folder.parent / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not (folder / "done").exists():
            shutil.rmtree(folder, ignore_errors=True)
            tree = copy.deepcopy(source.tree)
            if not isinstance(tree.get("output"), dict):
                tree["output"] = {}
            tree["output"]["checkpoint_steps"] = 1
            write_scene(source, dump(tree), folder)
            # More steps when the first ones are an initial stage, which
            # writes no checkpoint (docs/output.md).
            for steps in (2, 30, 200):
                r = run_command([str(Path(args.fissure).resolve()), "run", source.path.name,
                                 "-o", "out", "--max-steps", str(steps), "-q", "--no-plots"],
                                folder, args.timeout, args.memory_mb)
                if (folder / "out" / "checkpoint.h5").is_file():
                    break
                shutil.rmtree(folder / "out", ignore_errors=True)
            if not (folder / "out" / "checkpoint.h5").is_file():
                (folder / "failed.txt").write_text(
                    f"exit {r['rc']}: {first_error(r)}\n{r['stderr'][-2000:]}")
            (folder / "done").touch()
    return None if (folder / "failed.txt").exists() else folder


def corrupt(path, c, args, sources):
    """Applies corruption `c` (checkpoint_corruption) to the file at `path`:
    "changed", "unchanged" (zeros over zeros, another scene's checkpoint that
    is this one's) or "missing" (the other scene wrote none)."""
    rng = random.Random(c["seed"])
    original = path.read_bytes()
    data = bytearray(original)
    how = c["how"]
    if how == "flip":
        span = min(512, len(data)) if c["where"] == "record" else len(data)
        for offset in rng.sample(range(span), min(c["bytes"], span)):
            data[offset] ^= rng.randint(1, 255)
    elif how in ("scramble", "zero"):
        n = min(c["bytes"], len(data))
        offset = rng.randrange(len(data) - n + 1)
        data[offset:offset + n] = (bytes(n) if how == "zero"
                                   else bytes(rng.getrandbits(8) for _ in range(n)))
    elif how == "truncate":
        del data[rng.randrange(len(data)):]
    elif how == "extend":
        data += bytes(rng.getrandbits(8) for _ in range(c["bytes"]))
    elif how == "foreign":
        other = base_checkpoint(args, sources, c["scene"])
        if other is None:
            return "missing"
        data = bytearray((other / "out" / "checkpoint.h5").read_bytes())
    if data == original:
        return "unchanged"
    path.write_bytes(bytes(data))
    return "changed"


def digests(folder):
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def execute_restart(args, case, case_dir, result, finish):
    """A checkpoint case: the scene's base checkpoint, corrupted (or not),
    restarted. A corrupted one must be refused whole and touch no file of
    the output folder; an intact one must continue."""
    sources, c = WORKER["sources"], case["checkpoint"]
    scene_name = case["source"].path.name
    base = base_checkpoint(args, sources, case["source"].name)
    if base is None:
        return finish("CHECKPOINT-NOT-WRITTEN",
                      (Path(args.out) / "checkpoints" / case["source"].name /
                       "failed.txt").read_text()[:300])
    shutil.rmtree(case_dir, ignore_errors=True)
    shutil.copytree(base, case_dir)
    (case_dir / "done").unlink()
    checkpoint = case_dir / "out" / "checkpoint.h5"
    if c["how"] != "intact":
        outcome = corrupt(checkpoint, c, args, sources)
        if outcome == "missing":
            return finish("CHECKPOINT-NOT-WRITTEN", f"no checkpoint of {c['scene']}")
        if outcome == "unchanged":  # nothing is wrong with it
            c = dict(c, how="intact")
    before = digests(case_dir / "out")
    r = run_command([str(Path(args.fissure).resolve()), "run", scene_name, "--restart",
                     "out/checkpoint.h5", "--max-steps", str(args.max_steps + 2), "-q",
                     "--no-plots"], case_dir, args.timeout, args.memory_mb)
    result["processes"].append(r)
    cls = classify_process(r, "restart", scene_name)
    if cls is not None and cls[0] != "ERROR":
        return finish(*cls)
    refused = "error: the restart is refused" in r["stderr"]
    if c["how"] == "intact":
        if r["rc"] == 0:
            nan, _ = nan_in_output(case_dir / "out", r["stderr"])
            return finish("NAN", f"restart: {nan}") if nan else finish("RAN", "")
        if r["rc"] == 2:
            return finish("RUNTIME-STOP", f"restart: {first_error(r)}")
        return finish("INTACT-REFUSED", f"restart exit {r['rc']}: {first_error(r)}")
    if r["rc"] in (0, 2):
        return finish("CORRUPT-ACCEPTED", f"restart exit {r['rc']} from a checkpoint "
                                          f"corrupted by {c['how']}")
    if not refused:
        return finish("UNLOCATED", f"restart exit {r['rc']} without refusing the checkpoint: "
                                   f"{first_error(r)}")
    after = digests(case_dir / "out")
    changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
    if changed:
        return finish("OUTPUT-TOUCHED", f"refused, but changed {', '.join(changed[:5])}")
    return finish("REJECTED", first_error(r))


WORKER = {}  # args and sources, set before the pool forks


def run_case(index):
    args, sources = WORKER["args"], WORKER["sources"]
    case = make_case(sources, args.seed, index)
    source, data, ops = case["source"], case["data"], case["ops"]
    case_dir = Path(args.out) / "cases" / f"{index:05d}-{source.name}"
    if case_dir.exists():
        shutil.rmtree(case_dir)
    start = time.monotonic()
    result = execute(args, case, case_dir)
    result.update({"case": index, "ops": ops, "kinds": sorted(case["kinds"]), "bytes": len(data),
                   "seconds": round(time.monotonic() - start, 3)})
    bad = result["class"] not in OK_CLASSES
    if bad or args.keep_all:
        with open(case_dir / "case.json", "w") as f:
            json.dump(result, f, indent=1)
        if not args.keep_all:
            shutil.rmtree(case_dir / "out", ignore_errors=True)
    else:
        shutil.rmtree(case_dir, ignore_errors=True)
    # The report keeps short excerpts of the output only.
    for p in result["processes"]:
        p["stdout"] = p["stdout"][-2000:]
        p["stderr"] = p["stderr"][:2000]
    return result


# ---------------------------------------------------------------------------
# Minimising a reproducer


def signature(result):
    """What makes two failures the same: class and message without numbers and paths."""
    msg = re.sub(r"\S+\.ya?ml:\d+:\d+", "FILE:L:C", result.get("message", ""))
    msg = re.sub(r"'[^']*'", "'..'", msg)
    msg = re.sub(r"[-+]?\d+(\.\d+)?(e[-+]?\d+)?", "N", msg)
    return result["class"] + " | " + msg[:160]


def minimise(args, sources, result, budget_seconds):
    source = next(s for s in sources if s.name == result["scene"])
    kinds = set(result.get("kinds", []))
    original = Path(result["file"]).read_bytes()
    want = signature(result)
    work = Path(args.out) / "minimise" / f"{result['case']:05d}"
    deadline = time.monotonic() + budget_seconds
    trials = 0

    def fails(data):
        nonlocal trials
        trials += 1
        if work.exists():
            shutil.rmtree(work)
        r = execute(args, {"source": source, "data": data, "kinds": kinds, "checkpoint": None},
                    work)
        return signature(r) == want

    lines = original.split(b"\n")
    n = 2
    while len(lines) >= 2 and time.monotonic() < deadline:
        chunk = max(1, len(lines) // n)
        reduced = False
        for start in range(0, len(lines), chunk):
            if time.monotonic() >= deadline:
                break
            candidate = lines[:start] + lines[start + chunk:]
            if candidate and fails(b"\n".join(candidate)):
                lines = candidate
                n = max(n - 1, 2)
                reduced = True
                break
        if not reduced:
            if chunk == 1:
                break
            n = min(len(lines), n * 2)
    # Shorten very long lines by halving while the failure stays.
    for i in range(len(lines)):
        while len(lines[i]) > 200 and time.monotonic() < deadline:
            candidate = lines[:i] + [lines[i][: len(lines[i]) // 2]] + lines[i + 1:]
            if not fails(b"\n".join(candidate)):
                break
            lines = candidate
    shutil.rmtree(work, ignore_errors=True)
    data = b"\n".join(lines)
    path = Path(result["file"]).with_name("minimal-" + Path(result["file"]).name)
    path.write_bytes(data)
    return {"path": str(path), "bytes": len(data), "lines": len(lines), "trials": trials,
            "original_bytes": len(original)}


# ---------------------------------------------------------------------------
# Report


def write_report(args, results, elapsed, sources):
    out = Path(args.out)
    by_scene = defaultdict(Counter)
    for r in results:
        by_scene[r["scene"]][r["class"]] += 1
    totals = Counter(r["class"] for r in results)
    bad = [r for r in results if r["class"] not in OK_CLASSES]
    failing = [r for r in results if r["class"] in args.fail_on]
    groups = defaultdict(list)
    for r in bad:
        groups[signature(r)].append(r)
    report = {
        "seed": args.seed, "cases": len(results), "seconds": round(elapsed, 1),
        "max_steps": args.max_steps, "timeout": args.timeout, "memory_mb": args.memory_mb,
        "jobs": args.jobs, "fail_on": args.fail_on, "totals": dict(totals),
        "per_scene": {k: dict(v) for k, v in sorted(by_scene.items())},
        "h5_checked": HAVE_H5PY,
        "distinct_failures": [
            {"signature": sig, "count": len(rs), "class": rs[0]["class"],
             "cases": [r["case"] for r in rs], "reproducer": rs[0]["file"],
             "minimal": rs[0].get("minimal"), "ops": rs[0]["ops"], "message": rs[0]["message"]}
            for sig, rs in sorted(groups.items(), key=lambda kv: (CLASSES.index(kv[1][0]["class"]),
                                                                   -len(kv[1])))],
        "bad_cases": [{k: r[k] for k in ("case", "scene", "class", "message", "ops", "file",
                                          "seconds")} for r in bad],
        "slowest": sorted(({"case": r["case"], "scene": r["scene"], "class": r["class"],
                            "seconds": r["seconds"]} for r in results),
                           key=lambda x: -x["seconds"])[:10],
    }
    with open(out / "report.json", "w") as f:
        json.dump(report, f, indent=1)

    cols = [c for c in CLASSES if totals[c]] or CLASSES[-2:]
    md = ["# Scene fuzzer report", "",
          f"seed {args.seed}, {len(results)} cases, {elapsed:.0f} s wall on {args.jobs} jobs; "
          f"run --max-steps {args.max_steps}, time-out {args.timeout:g} CPU s, "
          f"address space {args.memory_mb} MB; results.h5 "
          f"{'checked' if HAVE_H5PY else 'NOT checked (no h5py)'}.", "",
          f"Failing classes: {', '.join(args.fail_on)}: **{len(failing)} case(s)**.", "",
          "| scene | " + " | ".join(cols) + " |", "|---|" + "---|" * len(cols)]
    for scene in sorted(by_scene):
        md.append(f"| {scene} | " + " | ".join(str(by_scene[scene][c]) for c in cols) + " |")
    md.append("| **total** | " + " | ".join(f"**{totals[c]}**" for c in cols) + " |")
    md += ["", "## Distinct failures", "",
           "Class and normalised message; the first case's reproducer (and its minimised "
           "version, when made).", ""]
    if not groups:
        md.append("None.")
    for item in report["distinct_failures"]:
        md.append(f"* **{item['class']}** x{item['count']} (cases "
                  f"{', '.join(map(str, item['cases'][:8]))}{' ...' if item['count'] > 8 else ''})"
                  f": `{item['message'][:240]}`")
        md.append(f"  - reproducer: `{item['reproducer']}`" +
                  (f", minimal: `{item['minimal']['path']}` ({item['minimal']['lines']} lines)"
                   if item.get("minimal") else ""))
        md.append(f"  - mutations: {'; '.join(item['ops'])[:300]}")
    md += ["", "## Slowest cases", ""]
    for s in report["slowest"]:
        md.append(f"* case {s['case']} ({s['scene']}, {s['class']}): {s['seconds']:.1f} s")
    md.append("")
    (out / "report.md").write_text("\n".join(md))
    return report, failing


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--fissure", default=str(REPO / "build" / "app" / "fissure"))
    p.add_argument("--configs", default=str(REPO / "configs"))
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--cases", type=int, default=300)
    p.add_argument("--case", type=int, nargs="*", help="run only these case numbers")
    p.add_argument("--out", default=str(REPO / "out" / "fuzz"))
    p.add_argument("--timeout", type=float, default=60,
                   help="CPU seconds per command (HANG past it, or past 5x + 30 s of wall time)")
    p.add_argument("--memory-mb", type=int, default=2048, help="address-space limit per command")
    p.add_argument("--sanitized", action="store_true",
                   help="fissure is built with AddressSanitizer: its memory limit instead of "
                        "RLIMIT_AS, and any sanitizer report is a CRASH")
    p.add_argument("--max-steps", type=int, default=3)
    p.add_argument("--checkpoint-share", type=float, default=CHECKPOINT_SHARE[0],
                   help="share of a run scene's cases that restart from a corrupted checkpoint")
    p.add_argument("--validate-seconds", type=float, default=10,
                   help="work budget of `validate` in a generator case (CPU seconds)")
    p.add_argument("--validate-mb", type=int, default=2048,
                   help="memory budget of `validate` in a generator case (peak resident MB)")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--max-size", type=int, default=100000,
                   help="largest list or polygon made (lines up to 20x that many bytes)")
    p.add_argument("--scenes", nargs="*", help="only these configs (stems)")
    p.add_argument("--minimise", action="store_true",
                   help="shrink one reproducer per distinct failure")
    p.add_argument("--minimise-seconds", type=float, default=60)
    p.add_argument("--keep-all", action="store_true", help="keep every case folder and output")
    p.add_argument("--fail-on",
                   help="classes that make the exit code 1 (comma-separated; default: "
                        "every class above VALIDATE-ACCEPTS-RUN-REJECTS, without OOM under "
                        "--sanitized)")
    p.add_argument("--quiet", action="store_true")
    args = p.parse_args()
    # Under the sanitizers the memory limit is ASan's, which the app's budget
    # does not see, and instrumented code needs 2-3 times its memory: OOM is
    # reported there, not failed.
    default = [c for c in FAIL_DEFAULT if not (args.sanitized and c == "OOM")]
    args.fail_on = [c for c in (args.fail_on or ",".join(default)).split(",") if c]
    MAX_SIZE[0] = args.max_size
    CHECKPOINT_SHARE[0] = args.checkpoint_share
    fuzz_common.SANITIZED[0] = args.sanitized

    if not Path(args.fissure).is_file():
        print(f"fuzz_scenes: no fissure executable at {args.fissure}", file=sys.stderr)
        return 2
    DOC_KEYS.extend(documented_keys(REPO))
    sources = [Source(f) for f in sorted(Path(args.configs).glob("*.yaml"))
               if not args.scenes or f.stem in args.scenes]
    out = Path(args.out)
    if not args.case:  # the base checkpoints too: the executable may have changed
        for folder in ("cases", "checkpoints"):
            shutil.rmtree(out / folder, ignore_errors=True)
    (out / "cases").mkdir(parents=True, exist_ok=True)
    # A copy of the executable: a rebuild during a long run changes nothing.
    shutil.copy2(args.fissure, out / "fissure")
    args.fissure = str(out / "fissure")
    indices = args.case if args.case else list(range(args.cases))
    start = time.monotonic()
    results = []
    WORKER.update(args=args, sources=sources)
    tasks = indices
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        for r in pool.imap_unordered(run_case, tasks):
            results.append(r)
            if not args.quiet and (r["class"] not in OK_CLASSES or len(results) % 100 == 0):
                print(f"[{len(results)}/{len(tasks)} {time.monotonic() - start:.0f}s] case "
                      f"{r['case']} {r['scene']}: {r['class']} {r['message'][:160]}", flush=True)
    results.sort(key=lambda r: r["case"])
    if args.minimise:
        seen = set()
        for r in results:
            if r["class"] in OK_CLASSES or signature(r) in seen:
                continue
            seen.add(signature(r))
            if r["seconds"] > 10:  # each trial would cost as much: not cheap
                continue
            if any(o.startswith("checkpoint:") for o in r["ops"]):  # the scene is intact
                continue
            r["minimal"] = minimise(args, sources, r, args.minimise_seconds)
            if not args.quiet:
                print(f"minimised case {r['case']}: {r['minimal']['original_bytes']} -> "
                      f"{r['minimal']['bytes']} bytes in {r['minimal']['trials']} trials",
                      flush=True)
    elapsed = time.monotonic() - start
    report, failing = write_report(args, results, elapsed, sources)
    totals = Counter(r["class"] for r in results)
    print(f"fuzz_scenes: seed {args.seed}, {len(results)} cases in {elapsed:.0f} s: " +
          ", ".join(f"{c} {totals[c]}" for c in CLASSES if totals[c]))
    print(f"fuzz_scenes: report {out / 'report.md'}")
    for r in failing[:20]:
        print(f"FAIL case {r['case']} ({r['scene']}) {r['class']}: {r['message'][:200]}\n"
              f"     reproducer: {r['file']}\n     mutations: {'; '.join(r['ops'])[:200]}")
    return 1 if failing else 0


if __name__ == "__main__":
    sys.setrecursionlimit(20000)  # PyYAML writes deeply nested values recursively
    sys.exit(main())
