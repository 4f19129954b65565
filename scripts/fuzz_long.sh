#!/usr/bin/env bash
# The long run of the scene fuzzer (docs/verification.md, "Scene fuzzer"):
# 10,000 seeded mutations of the scenes in configs/, lists and polygons up to
# 100,000 items, each validated and run for 3 steps under a 4 GB
# address-space limit and a time-out of 60 CPU seconds; one reproducer per distinct
# failure is minimised. Writes OUT/report.md and OUT/report.json, keeps the
# folder of every bad case in OUT/cases/, and exits 1 when there is a crash,
# a hang, an unlocated error or a NaN.
#
#   scripts/fuzz_long.sh                      # 10,000 cases, seed 2024, out/fuzz-long
#   CASES=2000 SEED=5 scripts/fuzz_long.sh    # fewer cases, another seed
#   scripts/fuzz_long.sh --case 123 417       # re-run single cases (same seed)
#
# Environment: BUILD_DIR (build), CASES (10000), SEED (2024), OUT
# (out/fuzz-long), JOBS (the number of cores). Other arguments go to
# tests/robustness/fuzz_scenes.py (--help). About 40 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}
scripts/install-deps.sh
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$BUILD_DIR" --target fissure -j "$JOBS"
exec /usr/bin/python3 tests/robustness/fuzz_scenes.py --fissure "$BUILD_DIR/app/fissure" \
  --cases "${CASES:-10000}" --seed "${SEED:-2024}" --out "${OUT:-out/fuzz-long}" \
  --jobs "$JOBS" --max-size 100000 --max-steps 3 --timeout 60 --memory-mb 4096 \
  --minimise "$@"
