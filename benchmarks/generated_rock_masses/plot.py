#!/usr/bin/python3
"""Plots and table of the generated-rock-mass benchmark (docs/performance.md,
"Generated rock masses").

    benchmarks/generated_rock_masses/plot.py [results.csv [results_before.csv]]

Reads the table run.py writes and, when it exists, the same benchmark run by
the code before the closing-contact fix (results_before.csv, kept for the
comparison in docs/performance.md), and writes generated_rock_masses.png
beside them: per generator the share of rock masses that ran to time.end,
the open-close iterations per step, the step cuts per accepted step, and the
CPU time of each run against its number of blocks. Prints the markdown table of the
docs.
"""
import csv
import statistics
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

here = Path(__file__).resolve().parent


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["ran"] = r["status"] == "completed"
        for k in ("steps", "cuts", "open_close_iterations", "blocks", "free_blocks"):
            r[k] = int(r[k]) if r[k] not in ("", None) else 0
        for k in ("wall_seconds", "cpu_seconds", "iterations_per_step"):
            r[k] = float(r[k]) if r.get(k) not in ("", None) else float("nan")
        r["cuts_per_step"] = r["cuts"] / r["steps"] if r["steps"] else float("nan")
    return rows


def family(generator):
    """The generators grouped for the figure: DFN by length law."""
    return generator if not generator.startswith("dfn_") else "dfn_*_" + \
        generator.split("_", 2)[2].replace("mises_", "")


def cpu(rows):
    """Median and largest CPU time, over the rows that have one (the code
    before's first 152 seeds were collected from their summaries: no CPU)."""
    t = [r["cpu_seconds"] for r in rows if r["cpu_seconds"] > 0]
    if not t:
        return "-"
    return f"{statistics.median(t):.2f}, {max(t):.1f}" + (f" ({len(t)} runs)" if len(t) < len(rows)
                                                          else "")


def table(rows, label):
    gens = sorted({r["generator"] for r in rows}, key=lambda g: (g.startswith("dfn"), g))
    print(f"\n{label}: {sum(r['ran'] for r in rows)} of {len(rows)} ran to the end\n")
    print("| generator | cases | ran to the end | blocks (median) | open-close it./step (median, max) "
          "| step cuts / step (mean) | CPU s (median, max) |")
    print("|---|---|---|---|---|---|---|")
    for g in gens + ["all"]:
        sub = [r for r in rows if g == "all" or r["generator"] == g]
        it = [r["iterations_per_step"] for r in sub if r["steps"]]
        print(f"| {g} | {len(sub)} | {sum(r['ran'] for r in sub)} | "
              f"{statistics.median(r['blocks'] for r in sub):.0f} | "
              f"{statistics.median(it):.2f}, {max(it):.2f} | "
              f"{statistics.mean(r['cuts_per_step'] for r in sub if r['steps']):.3f} | "
              f"{cpu(sub)} |")


def main():
    after_file = Path(sys.argv[1]) if len(sys.argv) > 1 else here / "results.csv"
    before_file = Path(sys.argv[2]) if len(sys.argv) > 2 else here / "results_before.csv"
    runs = [("after", read(after_file), "tab:blue")]
    if before_file.exists():
        before = read(before_file)
        # The code before did not report its blocks: the same scenes have them.
        blocks = {r["seed"]: r["blocks"] for r in runs[0][1]}
        for r in before:
            r["blocks"] = r["blocks"] or blocks.get(r["seed"], 0)
        runs.insert(0, ("before", before, "tab:red"))
    fams = sorted({family(r["generator"]) for _, rows, _ in runs for r in rows},
                  key=lambda g: (g.startswith("dfn"), g))
    fig, ax = plt.subplots(2, 2, figsize=(13, 9))
    width = 0.8 / len(runs)
    x = np.arange(len(fams))
    for k, (label, rows, color) in enumerate(runs):
        share = [np.mean([r["ran"] for r in rows if family(r["generator"]) == f]) for f in fams]
        ax[0, 0].bar(x + (k - (len(runs) - 1) / 2) * width, share, width, color=color,
                     label=f"{label}: {sum(r['ran'] for r in rows)} of {len(rows)}")
        for i, f in enumerate(fams):
            sub = [r for r in rows if family(r["generator"]) == f and r["steps"]]
            xs = i + (k - (len(runs) - 1) / 2) * width
            ax[0, 1].scatter([xs] * len(sub), [r["iterations_per_step"] for r in sub], s=8,
                             color=color, alpha=0.5, label=label if i == 0 else None)
            ax[1, 0].scatter([xs] * len(sub), [max(r["cuts_per_step"], 1e-3) for r in sub], s=8,
                             color=color, alpha=0.5, label=label if i == 0 else None)
        timed = [r for r in rows if r["cpu_seconds"] > 0]  # the code before: see its CSV
        ax[1, 1].scatter([r["blocks"] for r in timed], [r["cpu_seconds"] for r in timed], s=8,
                         color=color, alpha=0.5, label=label)
    for a in (ax[0, 0], ax[0, 1], ax[1, 0]):
        a.set_xticks(x)
        a.set_xticklabels(fams, rotation=35, ha="right", fontsize=8)
        a.legend(fontsize=8)
    ax[0, 0].set_ylabel("share that reached time.end (30 ms)")
    ax[0, 0].set_ylim(0, 1.05)
    ax[0, 1].set_ylabel("open-close iterations per accepted step")
    ax[1, 0].set_ylabel("step cuts per accepted step (0 drawn at 1e-3)")
    ax[1, 0].set_yscale("log")
    ax[1, 1].set_xlabel("blocks")
    ax[1, 1].set_ylabel("CPU time of the run (s)")
    ax[1, 1].set_xscale("log")
    ax[1, 1].set_yscale("log")
    ax[1, 1].legend(fontsize=8)
    fig.suptitle("Generated rock masses settling 30 ms under gravity from rest (dt <= 1 ms)")
    fig.tight_layout()
    out = after_file.parent / "generated_rock_masses.png"
    fig.savefig(out, dpi=90)
    print(f"wrote {out}")
    for label, rows, _ in runs:
        table(rows, label)


if __name__ == "__main__":
    main()
