#!/usr/bin/env bash
# Runs every benchmark driver that BUILD_DIR holds, then the plot scripts.
#
#   benchmarks/run_all.sh BUILD_DIR      (`make bench` calls it with its BUILD_DIR)
#
# Builds nothing itself: `make bench` builds first (the run.py drivers need
# BUILD_DIR/app/fissure). Each driver writes its
# results.csv into its own folder under benchmarks/; each plot script there
# (plot*.py) turns the CSV into PNGs. A driver that exits non-zero (a failed
# case) does not stop the others; the script's exit status is 1 if any did.
# Drivers run one after the other: their wall times are part of the results.
set -u

if [ $# -ne 1 ]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
build_dir=$1
here=$(cd "$(dirname "$0")" && pwd)
bench_bin="$build_dir/benchmarks"
if [ ! -d "$bench_bin" ]; then
  echo "$0: $bench_bin does not exist; build first (make bench)" >&2
  exit 2
fi

# Debian's numpy and matplotlib belong to the system interpreter; a python3
# earlier on PATH (pyenv, a venv) may not have them.
python=${PYTHON:-/usr/bin/python3}
[ -x "$python" ] || python=python3

status=0
for exe in "$bench_bin"/bench_*; do
  [ -x "$exe" ] || continue
  name=$(basename "$exe")
  echo "=== $name"
  start=$(date +%s)
  if ! "$exe"; then
    echo "=== $name FAILED" >&2
    status=1
  fi
  echo "=== $name: $(($(date +%s) - start)) s"
done

# Drivers that run the fissure executable on generated scenes (run.py BUILD_DIR).
for driver in "$here"/*/run.py; do
  [ -e "$driver" ] || continue
  echo "=== ${driver#"$here"/}"
  start=$(date +%s)
  "$python" "$driver" "$build_dir" || { echo "=== $driver FAILED" >&2; status=1; }
  echo "=== ${driver#"$here"/}: $(($(date +%s) - start)) s"
done

for script in "$here"/*/plot*.py; do
  [ -e "$script" ] || continue
  echo "=== ${script#"$here"/}"
  "$python" "$script" || { echo "=== $script FAILED" >&2; status=1; }
done
exit $status
