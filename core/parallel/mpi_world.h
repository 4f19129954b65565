// The MPI ranks of this program (docs/architecture.md 6). A program launched by
// mpirun (its launcher's environment says there are several ranks) starts
// MPI once, at its first call here; a program started alone makes no MPI
// call at all and is rank 0 of 1. `fissure rev` shares its realizations
// among the ranks; `fissure run` runs the scene on every rank, the
// processes that claim parallelism (their PETSc solvers) sharing
// their work, and rank 0 alone writes the output.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fissure::parallel {

/// The number of ranks the launcher started (1 without mpirun).
int launched_ranks();

/// Starts MPI when launched with several ranks (idempotent); finalized at exit.
void ensure_started();

/// This rank and the number of ranks (0 of 1 without mpirun).
int rank();
int size();

/// The largest of every rank's `value` (the value itself on one rank).
int all_max(int value);

/// Sums every rank's `values` (the same length on every rank) into each
/// rank's `values`: the whole of a vector each rank holds a share of. Makes
/// no MPI call on one rank.
void all_sum(std::span<double> values);
template <class Vector>
void all_sum(Vector& values) {
  all_sum(std::span<double>(values.data(), static_cast<std::size_t>(values.size())));
}

/// Concatenates each rank's `local` rows (equal row length) on rank 0, in
/// rank order; the other ranks get an empty vector.
std::vector<double> gather_to_root(const std::vector<double>& local);
std::vector<int> gather_ints_to_root(const std::vector<int>& local);

/// Rank 0's `values` (the same length on every rank) into every rank's.
void broadcast(std::span<double> values);
template <class Vector>
void broadcast(Vector& values) {
  broadcast(std::span<double>(values.data(), static_cast<std::size_t>(values.size())));
}
/// Rank 0's `value` on every rank.
int broadcast(int value);

}  // namespace fissure::parallel
