#include "core/parallel/mpi_world.h"

// The C API only: no C++ bindings (they need libmpi_cxx).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <cstdlib>

#include "core/base/errors.h"

namespace fissure::parallel {

int launched_ranks() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(var)) return std::max(1, std::atoi(v));
  return 1;
}

void ensure_started() {
  if (launched_ranks() <= 1) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  // Worker threads (the REV study's) do not call MPI; only the main thread does.
  FISSURE_CHECK(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) == MPI_SUCCESS,
                SolverError, "MPI could not be initialised");
  // Registered before PETSc's finalization (core/linear/petsc_session.cpp),
  // so run after it.
  std::atexit([] {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  });
}

namespace {
bool running() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}
}  // namespace

int rank() {
  int r = 0;
  if (running()) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  if (running()) MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int all_max(int value) {
  if (size() == 1) return value;
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

void all_sum(std::span<double> values) {
  if (size() == 1) return;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
}

namespace {
template <class T>
std::vector<T> gather_rows(const std::vector<T>& local, MPI_Datatype type) {
  if (size() == 1) return local;
  const int n = size(), me = rank();
  int count = static_cast<int>(local.size());
  std::vector<int> counts(n), offsets(n, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<T> all;
  if (me == 0) {
    for (int r = 1; r < n; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(offsets[n - 1] + counts[n - 1]);
  }
  MPI_Gatherv(local.data(), count, type, all.data(), counts.data(), offsets.data(), type, 0,
              MPI_COMM_WORLD);
  return all;
}
}  // namespace

std::vector<double> gather_to_root(const std::vector<double>& local) {
  return gather_rows(local, MPI_DOUBLE);
}

std::vector<int> gather_ints_to_root(const std::vector<int>& local) {
  return gather_rows(local, MPI_INT);
}

void broadcast(std::span<double> values) {
  if (size() == 1) return;
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

int broadcast(int value) {
  if (size() > 1) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

}  // namespace fissure::parallel
