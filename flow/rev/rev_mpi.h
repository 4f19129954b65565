// MPI for the REV study: when the program was launched by mpirun, the
// study's jobs are shared among the ranks (core/parallel/mpi_world.h), rank 0
// gathering the results. Otherwise one process, no MPI calls at all.
#pragma once

#include "flow/rev/rev_study.h"

namespace fissure::flow {

/// The context of this process (rank 0 of 1 when not launched by mpirun).
ParallelContext mpi_context();

}  // namespace fissure::flow
