#!/usr/bin/python3
"""Plot of benchmarks/sparse_lu (docs/performance.md "sparse_lu"):
factorization and solve time against the number of blocks for CHOLMOD's
Cholesky of S, the supernodal LU of A and UMFPACK's LU of A, and the cost per
column of a 32-column solve (a low-rank correction's set-up)."""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
LABELS = {
    "cholesky_of_S_float": "CHOLMOD Cholesky of S (float solve)",
    "supernodal_lu_float": "supernodal LU of A (float solve)",
    "umfpack_lu_double": "UMFPACK LU of A",
}

with open(HERE / "results.csv", newline="") as f:
    data = list(csv.DictReader(f))
fig, axes = plt.subplots(1, 3, figsize=(14, 4))
for method, label in LABELS.items():
    r = sorted((d for d in data if d["method"] == method), key=lambda d: int(d["blocks"]))
    n = [int(d["blocks"]) for d in r]
    axes[0].loglog(n, [1e3 * float(d["factorize_s"]) for d in r], "o-", label=label)
    axes[1].loglog(n, [1e3 * float(d["solve_s"]) for d in r], "o-", label=label)
    axes[2].loglog(n, [1e3 * float(d["per_column_s"]) for d in r], "o-", label=label)
for ax, title in zip(axes, ["factorization", "one solve", "per column of a 32-column solve"]):
    ax.set_xlabel("blocks (6 unknowns each)")
    ax.set_ylabel("ms (best of 5)")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
axes[0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(HERE / "sparse_lu.png", dpi=120)
