#!/usr/bin/python3
"""Markdown table and summary of the DDA stability sweep for docs/performance.md.

    benchmarks/dda_stability/table.py [results.csv]

Reads the CSV written by bench_dda_stability (default: results.csv beside this
script) and prints one table row per case, then the numbers the summary in
docs/performance.md quotes: failures, the largest displacements and what stiff
penalties cost (step cuts, open-close iterations per step, wall time).
PENALTIES is the sweep's order of penalties (plot.py uses it too).
Standard library only, so that it runs wherever the benchmark does.
"""
import csv
import sys
from pathlib import Path

PENALTIES = ("1E", "10E", "100E", "1000E", "auto")


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("dt", "end_time", "displacement", "kinetic_energy", "limit", "wall_seconds"):
            r[key] = float(r[key])
        for key in ("steps", "time_step_cuts", "open_close_iterations", "open_contacts", "passed"):
            r[key] = int(r[key])
        # Iterations per accepted step: 1 means every step converged at once.
        r["its_per_step"] = r["open_close_iterations"] / max(r["steps"], 1)
    return rows


def table(rows):
    lines = [
        "| scene | dt (s) | penalty | t end (s) | steps | cuts | open-close its | its/step "
        "| displacement (m) | open contacts | kinetic (J) | passed | wall (s) |",
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['scene']} | {r['dt']:.0e} | {r['penalty_factor']} | {r['end_time']:g} "
            f"| {r['steps']} | {r['time_step_cuts']} | {r['open_close_iterations']} "
            f"| {r['its_per_step']:.2f} | {r['displacement']:.3e} | {r['open_contacts']} "
            f"| {r['kinetic_energy']:.1e} | {'yes' if r['passed'] else '**no**'} "
            f"| {r['wall_seconds']:.2f} |")
    return "\n".join(lines)


def summary(rows):
    out = []
    failed = [r for r in rows if not r["passed"]]
    out.append(f"- {len(rows) - len(failed)} of {len(rows)} cases pass.")
    for scene in sorted({r["scene"] for r in rows}):
        sub = [r for r in rows if r["scene"] == scene]
        worst = max(sub, key=lambda r: r["displacement"])
        out.append(
            f"- {scene}: largest displacement {worst['displacement']:.3e} m "
            f"(dt = {worst['dt']:.0e} s, penalty {worst['penalty_factor']}), "
            f"{worst['displacement'] / worst['limit']:.1%} of the limit; "
            f"total wall time {sum(r['wall_seconds'] for r in sub):.1f} s.")
    wall = [r for r in rows if r["scene"] == "wall"]
    for dt in sorted({r["dt"] for r in wall}):
        sub = {r["penalty_factor"]: r for r in wall if r["dt"] == dt}
        parts = [f"{p}: {sub[p]['steps']} steps, {sub[p]['time_step_cuts']} cuts, "
                 f"{sub[p]['its_per_step']:.2f} its/step, {sub[p]['wall_seconds']:.1f} s"
                 for p in PENALTIES if p in sub]
        out.append(f"- wall, dt = {dt:.0e} s: " + "; ".join(parts) + ".")
    return "\n".join(out)


def main():
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("results.csv")
    rows = read(path)
    print(table(rows))
    print()
    print(summary(rows))


if __name__ == "__main__":
    main()
