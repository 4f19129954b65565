#!/usr/bin/python3
"""Plot of the block_cutting benchmark (docs/performance.md, section block_cutting).

    benchmarks/block_cutting/plot.py [results.csv]

Reads the CSV written by bench_block_cutting and writes cost.png beside it:
left, the wall time of generation and cutting (and of the cutting steps),
and the CPU time of cutting, against the number of fractures, log-log, with
the fitted exponents and a line of slope 1; right, the peak memory of each case above the program's
own baseline.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("results.csv")
    rows = list(csv.DictReader(path.open()))
    col = lambda key: np.array([float(r[key]) for r in rows])  # noqa: E731
    n = col("n_drawn")
    cut, gen = col("cutting_s"), col("generation_s")

    fig, (ax, am) = plt.subplots(1, 2, figsize=(10, 4.2))
    k = np.polyfit(np.log(n), np.log(cut), 1)
    ax.loglog(n, cut, "o-", color="C0", lw=2, label=f"cutting, wall (fit: N^{k[0]:.2f})")
    cpu = col("cutting_cpu_s")
    kc = np.polyfit(np.log(n), np.log(cpu), 1)
    ax.loglog(n, cpu, "o:", color="C0", lw=1, label=f"cutting, CPU (fit: N^{kc[0]:.2f})")
    steps = [("arrange_s", "exact arrangement"), ("merge_s", "merging"),
             ("extract_s", "block extraction"), ("graph_s", "fracture graph")]
    for i, (key, label) in enumerate(steps):
        ax.loglog(n, np.maximum(col(key), 1e-5), ".--", color=f"C{i + 2}", lw=1, label=label)
    ax.loglog(n, gen, "s-", color="C1", label="generation")
    ref = cut[0] * n / n[0]
    ax.loglog(n, ref, ":", color="grey", label="slope 1")
    ax.axhline(2.0, color="red", lw=0.8)
    ax.text(n[0], 2.2, "target for 1e4: 2 s", color="red", fontsize=8)
    ax.set_xlabel("fractures drawn N")
    ax.set_ylabel("wall time (s), one core")
    load = float(rows[0]["load_average"])
    ax.set_title(f"Cost at fixed density (load {load:.1f})")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)

    mem = col("peak_rss_mb") - col("baseline_rss_mb")
    am.loglog(n, np.maximum(mem, 0.1), "o-", color="C0", label="peak RSS above baseline")
    am.loglog(n, np.maximum(mem[-1], 0.1) * n / n[-1], ":", color="grey", label="slope 1")
    am.set_xlabel("fractures drawn N")
    am.set_ylabel("MB")
    am.set_title(f"Peak memory (baseline {rows[0]['baseline_rss_mb']} MB)")
    am.legend(fontsize=7)
    am.grid(True, which="both", alpha=0.3)

    fig.tight_layout()
    out = path.with_name("cost.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
