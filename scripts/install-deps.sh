#!/usr/bin/env bash
# Installs Fissure's build and test dependencies from Debian packages.
# Idempotent: when every package is already installed it does nothing (no
# network access), so `make run` and `make test` can call it every time.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev          # dense/sparse linear algebra
  libsuitesparse-dev     # CHOLMOD Cholesky, UMFPACK LU (direct solvers)
  libopenblas0-serial    # optimised BLAS for them, single-threaded (small dense
                         # fronts: a threaded BLAS only burns system time)
  libsundials-dev        # CVODE/IDA time integrators
  petsc-dev openmpi-bin  # PETSc KSP solvers (+ MPI, hypre)
  libhdf5-dev            # results.h5 (the OpenMPI build that PETSc links)
  libyaml-cpp-dev        # scene files
  libcli11-dev           # command line
  libfmt-dev libspdlog-dev
  nlohmann-json3-dev     # summary.json
  libcgal-dev            # exact-predicate polygon operations
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib python3-h5py  # plots
  python3-yaml           # tests/robustness/fuzz_scenes.py (scene fuzzer)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
