#include "core/linear/block_solver.h"

#include "core/base/errors.h"

namespace fissure {

std::unique_ptr<BlockSolver> make_block_solver(const LinearSolverControls& c) {
  switch (c.type) {
    case LinearSolverControls::Type::Auto:
    case LinearSolverControls::Type::Direct: return make_direct_solver();
    case LinearSolverControls::Type::Pcg: return make_pcg_solver(c.relative_tolerance, c.max_iterations);
    case LinearSolverControls::Type::Petsc: return make_petsc_solver(c);
  }
  throw SolverError("unknown linear solver type");
}

}  // namespace fissure
