#include "flow/rev/rev_mpi.h"

#include "core/parallel/mpi_world.h"

namespace fissure::flow {

ParallelContext mpi_context() {
  ParallelContext c;
  parallel::ensure_started();
  c.rank = parallel::rank();
  c.size = parallel::size();
  c.gather = parallel::gather_to_root;
  return c;
}

}  // namespace fissure::flow
