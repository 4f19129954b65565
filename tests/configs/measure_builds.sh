#!/usr/bin/env bash
# Runs every config's CI line with each build variant and run-time variant
# that a user's machine may legitimately differ in, one output folder per
# variant, for measure_spread.py (tests/configs/README.md, "Measured spread").
#
#   tests/configs/measure_builds.sh OUT NATIVE PORTABLE AVX2 CONTRACT
#
# NATIVE, PORTABLE, AVX2, CONTRACT: build folders configured with the default
# -march=native, -DFISSURE_CPU_ARCHITECTURE= (x86-64, SSE2),
# -DFISSURE_CPU_ARCHITECTURE=x86-64-v3 (AVX2 + FMA) and
# -DFISSURE_FP_CONTRACT=fast (native, the compiler free to fuse a * b + c),
# each with its fissure target built. The run-time variants: OpenBLAS's
# kernels for other CPUs (OPENBLAS_CORETYPE: what CHOLMOD and UMFPACK call on
# them), glibc's libm without its FMA code paths, and one hardware thread
# (taskset: the REV study's threads). A variant the machine cannot run (the
# AVX-512 kernels on a CPU without AVX-512) is skipped with a message.
# ONLY=REGEX runs only the variants whose name matches.
# Then: python3 tests/configs/measure_spread.py OUT/*
set -uo pipefail
if [ $# -ne 5 ]; then
  sed -n '2,18p' "$0" >&2
  exit 2
fi
out=$1
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
declare -A app=([native]=$2/app/fissure [portable]=$3/app/fissure [avx2]=$4/app/fissure [contract]=$5/app/fissure)
has_avx512=$(grep -q -w avx512f /proc/cpuinfo && echo 1 || echo 0)

run() {  # run NAME BUILD [ENV=VALUE ...]
  local name=$1 build=$2
  shift 2
  if [ -n "${ONLY:-}" ] && ! [[ $name =~ $ONLY ]]; then
    return
  fi
  if [ ! -x "${app[$build]}" ]; then
    echo "measure_builds: ${app[$build]} is not built; $name skipped" >&2
    return
  fi
  echo "== $name"
  env "$@" python3 "$here/run_config_ci_lines.py" "${app[$build]}" "$source_dir" "$out/$name" --no-compare |
    grep -v -- "-> ok$" || true
}

run native native
run native_blas_haswell native OPENBLAS_CORETYPE=Haswell
run native_blas_sandybridge native OPENBLAS_CORETYPE=Sandybridge
run native_blas_prescott native OPENBLAS_CORETYPE=Prescott
if [ "$has_avx512" = 1 ]; then
  run native_blas_skylakex native OPENBLAS_CORETYPE=SkylakeX
else
  echo "measure_builds: no AVX-512 on this CPU; the SkylakeX BLAS kernels skipped" >&2
fi
run native_libm_without_fma native GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2_Usable,-FMA_Usable,-AVX2,-FMA
run native_one_thread native taskset -c 0
run portable portable
run portable_blas_prescott portable OPENBLAS_CORETYPE=Prescott
run avx2 avx2
run avx2_blas_sandybridge avx2 OPENBLAS_CORETYPE=Sandybridge
run contract contract
