#!/usr/bin/env python3
"""Generated rock masses settling under gravity (issue 22, item 1).

Writes one DDA scene per seed from the rock-mass generators of
docs/rock-mass.md, runs `fissure run` on it for a short settle from rest
(`--settle` seconds of simulated time at 1 ms steps) and records how it went:
status, steps, step cuts, open-close iterations per step, held contacts, the
blocks and the smallest free one, wall and CPU time. The generator of a seed is
`GENERATORS[seed % len(GENERATORS)]`, so any run of consecutive seeds covers
every generator evenly; its parameters are drawn from the seed:

  joint_sets        two sets in a box: spacing, spread, phase, dip drawn; one
                    persistent, one of joints with rock bridges (stagger drawn
                    or random)
  joint_sets_slope  the same on a slope profile (face angle drawn)
  dfn_<o>_<l>       one DFN family per orientation law o (fixed, uniform,
                    von_mises) and length law l (constant, uniform,
                    exponential, log_normal, truncated_power_law) and a
                    second family of uniform orientations
  excavation        a DFN around a circular tunnel or a rectangular cavern
  slope_dfn         a DFN in a slope profile

Every scene keeps the default merge tolerance (1e-5 of the domain's extent),
so its rock mass has the slivers, T-junctions, shared corners and dangling
fracture ends of the generator, blocks down to mm size.

A case *runs to its end* when its status is `completed` (time.end reached).
`diverged` (a step could not be completed above time.min_step), an error,
`max_steps` (more than --max-steps steps: the step was cut far below 1 ms for
good) or a timeout fail it. With --check the exit status is 1 when any case
did not run to its end (the ctest robustness.generated_rock_masses).

Usage: generated_rock_masses.py --fissure BIN --out DIR [--first-seed S]
       [--cases N] [--settle T] [--max-steps K] [--jobs J] [--timeout SEC]
       [--csv FILE] [--check] [--quiet]
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import pathlib
import random
import shutil
import subprocess
import sys
import threading
import time

ORIENTATIONS = ["fixed", "uniform", "von_mises"]
LENGTHS = ["constant", "uniform", "exponential", "log_normal", "truncated_power_law"]
GENERATORS = (["joint_sets", "joint_sets_slope"] +
              [f"dfn_{o}_{l}" for o in ORIENTATIONS for l in LENGTHS] +
              ["excavation", "slope_dfn"])
# Not in the default mix (hundreds to a thousand blocks, minutes per case):
# `--generator dense_dfn`.
OPT_IN_GENERATORS = ["dense_dfn"]

FIELDS = ["seed", "generator", "status", "steps", "simulated_time", "cuts", "cuts_open_close",
          "cuts_displacement", "open_close_iterations", "iterations_per_step",
          "max_iterations_in_a_step", "held_contacts", "blocks", "free_blocks",
          "smallest_free_area", "max_penetration", "wall_seconds", "cpu_seconds", "message"]


def flow_list(items):
    return "[" + ", ".join(items) + "]"


def point(p):
    return f"[{p[0]:.6g}, {p[1]:.6g}]"


def polygon(points):
    return flow_list(point(p) for p in points)


def mapping(d):
    return "{" + ", ".join(f"{k}: {v}" for k, v in d.items()) + "}"


def orientation_law(rng, law):
    if law == "fixed":
        return mapping({"distribution": "fixed", "value": f"{rng.uniform(0, 180):.4g}"})
    if law == "uniform":
        return mapping({"distribution": "uniform"})
    return mapping({"distribution": "von_mises", "mean": f"{rng.uniform(0, 180):.4g}",
                    "kappa": f"{rng.choice([2, 5, 10, 20, 50]):g}"})


def length_law(rng, law, scale):
    """A length law whose mean is about `scale` (m)."""
    m = scale * rng.uniform(0.6, 1.5)
    if law == "constant":
        return mapping({"distribution": "constant", "value": f"{m:.4g} m"})
    if law == "uniform":
        return mapping({"distribution": "uniform", "min": f"{0.3 * m:.4g} m",
                        "max": f"{1.7 * m:.4g} m"})
    if law == "exponential":
        return mapping({"distribution": "exponential", "mean": f"{m:.4g} m"})
    if law == "log_normal":
        return mapping({"distribution": "log_normal", "mean": f"{m:.4g} m",
                        "std": f"{m * rng.uniform(0.3, 1.0):.4g} m"})
    return mapping({"distribution": "truncated_power_law",
                    "exponent": f"{rng.uniform(1.5, 3.0):.3g}",
                    "min": f"{0.3 * m:.4g} m", "max": f"{8 * m:.4g} m"})


def aperture_law(rng):
    kind = rng.choice(["constant", "log_normal", "length_correlated"])
    if kind == "constant":
        return "100 um"
    if kind == "log_normal":
        return mapping({"distribution": "log_normal", "mean": "80 um", "std": "30 um"})
    return mapping({"distribution": "length_correlated", "factor": "20 um", "exponent": "0.5"})


def dfn_family(rng, name, orientation, length, size, joint, share=1.0):
    """A family of mean length about size / 4 and dimensionless density
    P21 x mean length of 3-5 (times `share`), well above percolation."""
    scale = size / rng.uniform(3, 5)
    p21 = share * rng.uniform(3, 5) / scale
    if rng.random() < 0.5:
        density = f"{{p21: {p21:.4g} 1/m}}"
    else:
        density = f"{{p20: {p21 / scale:.4g} 1/m^2}}"
    return ("    - " + mapping({"name": name, "density": density,
                                "orientation": orientation_law(rng, orientation),
                                "length": length_law(rng, length, scale),
                                "aperture": aperture_law(rng), "joint": joint}))


def joint_set(rng, name, size, persistent, joint):
    spacing = size / rng.uniform(9, 15)
    d = {"name": name, "dip": f"{rng.uniform(0, 180):.4g}", "spacing": f"{spacing:.4g} m",
         "spacing_spread": f"{spacing * rng.uniform(0, 0.4):.4g} m",
         "phase": f"{rng.uniform(0, 0.99):.3g}", "joint": joint}
    if not persistent:
        trace = spacing * rng.uniform(1.5, 4)
        d["trace_length"] = f"{trace:.4g} m"
        d["bridge_length"] = f"{trace * rng.uniform(0.1, 0.6):.4g} m"
        d["stagger"] = "random" if rng.random() < 0.5 else f"{rng.uniform(0, 0.95):.3g}"
    return "    - " + mapping(d)


def box(w, h):
    return [(0, 0), (w, 0), (w, h), (0, h)]


def slope(rng, w, h):
    """A slope profile: toe at 0.3 w, crest at 0.3 w + h_face / tan(face)."""
    face = math.radians(rng.uniform(30, 70))
    base = h * rng.uniform(0.25, 0.45)
    face_height = h - base
    toe = 0.3 * w
    crest = min(toe + face_height / math.tan(face), 0.85 * w)
    return [(0, 0), (w, 0), (w, h), (crest, h), (toe, base), (0, base)]


def scene_text(seed, generator, settle):
    """The scene of one case (YAML), deterministic for (seed, generator)."""
    rng = random.Random(f"{generator}:{seed}")
    size = rng.uniform(10, 25)
    w, h = size, size * rng.uniform(0.6, 1.0)
    domain = box(w, h)
    fixed = "[bottom, left, right]"
    excavations = []
    sets, families = [], []
    if generator.startswith("joint_sets"):
        if generator == "joint_sets_slope":
            w = size * 1.5
            domain = slope(rng, w, h)
            fixed = "[bottom, right]"
        else:
            fixed = "[bottom]"  # free sides: a box whose every block touches a side
        sets.append(joint_set(rng, "persistent", size, True, "rough"))
        sets.append(joint_set(rng, "bridged", size, False, "smooth"))
    elif generator.startswith("dfn_"):
        orientation, length = generator[4:].split("_", 1)
        if orientation == "von":  # von_mises
            orientation, length = "von_mises", length.split("_", 1)[1]
        # A family of one direction cuts no blocks alone: a second family,
        # uniform, always (both at 0.6 of the density).
        families.append(dfn_family(rng, "main", orientation, length, size, "rough", 0.6))
        families.append(dfn_family(rng, "other", "uniform", rng.choice(LENGTHS), size, "smooth",
                                   0.6))
    elif generator == "excavation":
        cx, cy = w / 2, h * rng.uniform(0.4, 0.6)
        r = min(w, h) * rng.uniform(0.1, 0.2)
        if rng.random() < 0.5:
            shape = mapping({"circle": mapping({"centre": point((cx, cy)),
                                                "radius": f"{r:.4g} m",
                                                "segments": rng.choice([16, 24, 48])})})
        else:
            shape = mapping({"vertices": polygon([(cx - 1.5 * r, cy - r), (cx + 1.5 * r, cy - r),
                                                  (cx + 1.5 * r, cy + r), (cx - 1.5 * r, cy + r)])})
        excavations.append("    - {name: opening, " + shape[1:])
        families.append(dfn_family(rng, "main", "von_mises", rng.choice(LENGTHS), size, "rough",
                                   0.8))
        families.append(dfn_family(rng, "other", rng.choice(ORIENTATIONS), rng.choice(LENGTHS),
                                   size, "smooth", 0.8))
    elif generator == "dense_dfn":
        # Twice the density of the other DFNs (P21 x mean length 6-10 per
        # family): slivers and fans of thin blocks around shared corners, as
        # in dfn_network.yaml with a family's P21 doubled (fuzz case 4143).
        families.append(dfn_family(rng, "main", rng.choice(ORIENTATIONS), rng.choice(LENGTHS),
                                   size, "rough", 2.0))
        families.append(dfn_family(rng, "other", "uniform", rng.choice(LENGTHS), size, "smooth",
                                   2.0))
    elif generator == "slope_dfn":
        w = size * 1.5
        domain = slope(rng, w, h)
        fixed = "[bottom, right]"
        families.append(dfn_family(rng, "main", rng.choice(ORIENTATIONS), rng.choice(LENGTHS),
                                   size, "rough", 0.6))
        families.append(dfn_family(rng, "other", rng.choice(ORIENTATIONS), rng.choice(LENGTHS),
                                   size, "smooth", 0.6))
    else:
        raise ValueError(f"unknown generator {generator}")

    lines = [f"# generated_rock_masses.py: seed {seed}, generator {generator}",
             f"name: {generator}_{seed}",
             "physics: [mechanics]",
             "materials:",
             "  - {name: rock, density: 2600 kg/m^3, young_modulus: 30 GPa, poisson_ratio: 0.25}",
             "joints:",
             f"  - {{name: rough, friction_angle: {rng.uniform(30, 45):.3g}, cohesion: 0}}",
             f"  - {{name: smooth, friction_angle: {rng.uniform(20, 35):.3g}, cohesion: 0}}",
             "rock_mass:",
             f"  domain: {polygon(domain)}",
             f"  seed: {seed}"]
    if excavations:
        lines += ["  excavations:"] + excavations
    if sets:
        lines += ["  joint_sets:"] + sets
    if families:
        lines += ["  dfn:"] + families
    lines += [f"  fixed_blocks: {{boundaries: {fixed}}}",
              "mechanics: {dda: {time_step: 1 ms}}",
              f"time: {{end: {settle:g}}}",
              "output: {hdf5: false}", ""]
    return "\n".join(lines)


def generator_of(seed):
    return GENERATORS[seed % len(GENERATORS)]


def run_case(fissure, out, seed, settle, max_steps, timeout, generator=None):
    generator = generator or generator_of(seed)
    folder = pathlib.Path(out) / f"{seed:05d}_{generator}"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    scene = folder / "scene.yaml"
    scene.write_text(scene_text(seed, generator, settle))
    row = {f: "" for f in FIELDS}
    row.update(seed=seed, generator=generator)
    start = time.monotonic()
    log = folder / "run.log"
    with open(log, "w") as out:
        child = subprocess.Popen([fissure, "run", str(scene), "-q", "--no-plots", "-o",
                                  str(folder / "out"), "--max-steps", str(max_steps)],
                                 stdout=out, stderr=out)
    timer = threading.Timer(timeout, child.kill)
    timer.start()
    # wait4: the CPU time of this run alone (the cases run in parallel).
    _, wait_status, usage = os.wait4(child.pid, 0)
    timed_out = not timer.is_alive()
    timer.cancel()
    row["wall_seconds"] = f"{time.monotonic() - start:.3f}"
    row["cpu_seconds"] = f"{usage.ru_utime + usage.ru_stime:.3f}"
    if timed_out:
        row.update(status="timeout")
        return row
    summary_file = folder / "out" / "summary.json"
    if not summary_file.exists():
        message = log.read_text().strip().splitlines()
        row.update(status=f"error (exit status {os.waitstatus_to_exitcode(wait_status)})",
                   message=message[-1][:200] if message else "")
        return row
    s = json.loads(summary_file.read_text())
    m = s["processes"]["mechanics"]
    cuts = m["time_step_cuts"]
    steps = max(m["steps"], 1)
    blocks = m.get("blocks", {})
    row.update(status=s["status"], steps=m["steps"], simulated_time=s["simulated_time"],
               cuts=cuts["open_close"] + cuts["displacement_ratio"],
               cuts_open_close=cuts["open_close"], cuts_displacement=cuts["displacement_ratio"],
               open_close_iterations=m["open_close_iterations"],
               iterations_per_step=f"{m['open_close_iterations'] / steps:.4g}",
               max_iterations_in_a_step=m["max_open_close_iterations_in_a_step"],
               held_contacts=m["held_contacts"], blocks=blocks.get("total", ""),
               free_blocks=blocks.get("free", ""),
               smallest_free_area=blocks.get("smallest_free_area", ""),
               max_penetration=m["max_penetration"],
               message=(s.get("message") or "")[:200])
    return row


def runs_to_end(row):
    return row["status"] == "completed"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--fissure", required=True)
    ap.add_argument("--out", required=True, help="one folder per case (scene.yaml, out/)")
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=len(GENERATORS))
    ap.add_argument("--settle", type=float, default=0.03, help="simulated seconds (1 ms steps)")
    ap.add_argument("--max-steps", type=int, default=1000)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=300, help="wall seconds per case")
    ap.add_argument("--csv", help="results table (default OUT/results.csv)")
    ap.add_argument("--check", action="store_true", help="exit 1 unless every case ran to its end")
    ap.add_argument("--quiet", action="store_true")
    ap.add_argument("--generator", choices=GENERATORS + OPT_IN_GENERATORS,
                    help="every case from this generator (default: seed modulo the default mix)")
    a = ap.parse_args()

    seeds = range(a.first_seed, a.first_seed + a.cases)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = [pool.submit(run_case, a.fissure, a.out, s, a.settle, a.max_steps, a.timeout,
                               a.generator) for s in seeds]
        for f in futures:
            row = f.result()
            rows.append(row)
            if not a.quiet or not runs_to_end(row):
                print(f"seed {row['seed']:>5} {row['generator']:<32} {row['status']:<10} "
                      f"steps {row['steps']:>5} cuts {row['cuts']:>4} "
                      f"it/step {row['iterations_per_step']:>6} blocks {row['blocks']:>5} "
                      f"{row['cpu_seconds']:>8} s CPU {row['message']}", flush=True)
    table = pathlib.Path(a.csv) if a.csv else pathlib.Path(a.out) / "results.csv"
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    ran = sum(runs_to_end(r) for r in rows)
    print(f"{ran} of {len(rows)} generated rock masses ran to their end "
          f"(settle {a.settle:g} s); table {table}")
    if a.check and ran != len(rows):
        for r in rows:
            if not runs_to_end(r):
                print(f"FAILED: seed {r['seed']} ({r['generator']}): {r['status']} "
                      f"{r['message']}; reproduce: {a.out}/{r['seed']:05d}_{r['generator']}"
                      f"/scene.yaml", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
