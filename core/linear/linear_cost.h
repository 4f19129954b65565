// Modelled cost of sparse linear algebra, in seconds of a nominal core, from
// operation and memory counts. The solvers that adapt (the `auto` choice
// between Krylov and a reused factorization, when to renew a factor, how
// large a low-rank correction may grow) compare these model costs instead
// of measured times: a decision by counts is the same on every run,
// whatever the load of the machine, so that a scene's results are
// reproducible to the bit (issue 22, item 5). The two rates were fitted to
// the measured costs of the DDA brick walls on the 2-core development
// machine (docs/performance.md "Reproducible solver choices"); they set
// where the choices fall, not whether a result is right.
#pragma once

namespace fissure::linear_cost {

/// Dense supernodal kernels (BLAS-3 updates of a factorization), double.
inline constexpr double kFactorFlopsPerSecond = 1e10;
/// Kernels that stream memory (sparse products, triangular solves, vector
/// updates): bytes read or written per second.
inline constexpr double kStreamBytesPerSecond = 1.2e10;

/// A factorization of `flops` operations in double (half the time in float).
inline double factorization(double flops, bool single_precision) {
  return flops / (single_precision ? 2 * kFactorFlopsPerSecond : kFactorFlopsPerSecond);
}

/// A pass over `bytes` of memory.
inline double stream(double bytes) {
  return bytes / kStreamBytesPerSecond;
}

/// y = A x with `stored_blocks` dense 6x6 blocks in double.
inline double block_product(double stored_blocks) {
  return stream(stored_blocks * 36 * 8);
}

/// `count` vector operations (axpy, dot) on vectors of `n` doubles.
inline double vector_operations(double count, double n) {
  return stream(count * n * 16);
}

}  // namespace fissure::linear_cost
