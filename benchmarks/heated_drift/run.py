#!/usr/bin/env python3
"""Benchmark: the heated drift (configs/heated_drift.yaml; docs/thermal.md
section 10) over its coupling interval and splitting scheme (issue 23).

Runs the scene over END years with the flow and the mechanics updated every
T (the `coupling.intervals` of both; the thermal steps stay as the scene
has them), T over two decades, with Lie splitting, and at the scene's T
with Strang; every run one process at a time. From each run: the wall time
and its split by process (summary.json processes.coordinator.coupling.
seconds), the quasi-static updates still moving at their end, and the state
at END: the monitors' temperatures and displacements and the block stress
at the side wall. The finest T is the reference of the convergence table:
each quantity's difference from it. Writes results.csv and
heated_drift_convergence.png here.

Usage: run.py BUILD_DIR [--end YEARS] [--intervals T1,T2,...]
"""
import argparse
import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
SCENE = root / "configs" / "heated_drift.yaml"
YEAR = 3.15576e7


def variant(text, interval, scheme, end):
    """The scene with both intervals T (years), the scheme and the end time."""
    scene = text.replace("  intervals: {mechanics: 0.5 yr, flow: 0.5 yr}",
                         f"  intervals: {{mechanics: {interval} yr, flow: {interval} yr}}")
    scene = scene.replace("  scheme: lie", f"  scheme: {scheme}")
    scene = scene.replace("  end: 10 yr", f"  end: {end} yr")
    scene = scene.replace("  interval: 1 yr", f"  interval: {end} yr")
    assert scene.count(f"{interval} yr, flow") == 1, "the scene's coupling section changed"
    return scene


def run(fissure, text, interval, scheme, end, workdir):
    name = f"t{interval}_{scheme}"
    scene = pathlib.Path(workdir) / f"{name}.yaml"
    scene.write_text(variant(text, interval, scheme, end))
    out = pathlib.Path(workdir) / name
    subprocess.run([str(fissure), "run", str(scene), "-o", str(out), "-q", "--no-plots"],
                   check=True, stdout=subprocess.DEVNULL)
    s = json.loads((out / "summary.json").read_text())
    coupling = s["processes"]["coordinator"]["coupling"]
    row = {"interval_yr": interval, "scheme": scheme, "status": s["status"],
           "wall_s": s["wall_seconds"]}
    for p, sec in coupling["seconds"].items():
        row[f"{p}_s"] = sec
    row["mechanics_updates"] = coupling["updates"]["mechanics"]
    row["not_at_rest"] = coupling["quasi_static"]["not_at_rest"]["mechanics"]
    m = s["monitors"]
    for mon in ("wall", "rock_2m", "rock_5m", "crown"):
        row[f"{mon}_T"] = m[mon]["T"]
        row[f"{mon}_ux"] = m[mon]["ux"]
    row["wall_syy"] = m["wall"]["syy"]
    row["aperture_max"] = s["processes"]["flow"]["aperture"]["max"]
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build_dir")
    ap.add_argument("--end", type=float, default=5)
    ap.add_argument("--intervals", default="2.5,1,0.5,0.25,0.1,0.05")
    args = ap.parse_args()
    fissure = pathlib.Path(args.build_dir) / "app" / "fissure"
    text = SCENE.read_text()
    intervals = [float(t) for t in args.intervals.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as workdir:
        for t in intervals:
            rows.append(run(fissure, text, t, "lie", args.end, workdir))
            print(f"T = {t:5g} yr lie: {rows[-1]['wall_s']:6.1f} s", flush=True)
        rows.append(run(fissure, text, 0.5, "strang", args.end, workdir))
        print(f"T =   0.5 yr strang: {rows[-1]['wall_s']:6.1f} s", flush=True)
    ref = min((r for r in rows if r["scheme"] == "lie"), key=lambda r: r["interval_yr"])
    keys = ["wall_T", "rock_2m_T", "rock_5m_T", "wall_ux", "rock_5m_ux", "wall_syy", "aperture_max"]
    for r in rows:
        for k in keys:
            r[f"d_{k}"] = abs(r[k] - ref[k])
    with open(here / "results.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print(f"\nheated drift, {args.end:g} years; differences from T = {ref['interval_yr']:g} yr")
    print("T (yr) scheme  wall s  mech s  therm s  flow s  not_at_rest  |dT wall| K  "
          "|d ux wall| m  |d ux 5m| m  |d syy wall| Pa")
    for r in rows:
        print(f"{r['interval_yr']:6g} {r['scheme']:6s} {r['wall_s']:7.1f} {r['mechanics_s']:7.1f} "
              f"{r['thermal_s']:8.2f} {r['flow_s']:7.3f} {r['not_at_rest']:12d} "
              f"{r['d_wall_T']:12.3g} {r['d_wall_ux']:14.3g} {r['d_rock_5m_ux']:12.3g} "
              f"{r['d_wall_syy']:14.3g}")
    plot(rows, ref)
    return 0


def plot(rows, ref):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot")
        return
    lie = [r for r in rows if r["scheme"] == "lie" and r is not ref]
    t = [r["interval_yr"] for r in lie]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, label in (("d_wall_T", "wall T (K)"), ("d_rock_5m_T", "T 5 m (K)"),
                       ("d_wall_ux", "wall ux (m)"), ("d_rock_5m_ux", "ux 5 m (m)"),
                       ("d_wall_syy", "wall syy (MPa)")):
        scale = 1e-6 if "syy" in key else 1
        a.loglog(t, [max(r[key] * scale, 1e-16) for r in lie], "o-", label=label)
    a.set_xlabel("coupling interval of flow and mechanics T (years)")
    a.set_ylabel(f"|difference from T = {ref['interval_yr']:g} yr|")
    a.set_title("convergence in the coupling interval (Lie)")
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=8)
    all_t = [r["interval_yr"] for r in rows if r["scheme"] == "lie"]
    lie_all = [r for r in rows if r["scheme"] == "lie"]
    for p, colour in (("mechanics", "C0"), ("thermal", "C1"), ("flow", "C2")):
        b.loglog(all_t, [max(r[f"{p}_s"], 1e-4) for r in lie_all], "o-", color=colour, label=p)
    b.loglog(all_t, [r["wall_s"] for r in lie_all], "k--", label="whole run")
    b.set_xlabel("coupling interval T (years)")
    b.set_ylabel("wall time (s)")
    b.set_title("cost by process")
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(here / "heated_drift_convergence.png", dpi=110)


if __name__ == "__main__":
    sys.exit(main())
