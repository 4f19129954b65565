// The `solver` map of a scene section (each process that solves a linear system):
// type, tolerance, iteration limit and PETSc options, with the same checks
// for every section (PETSc options only where PETSc is used; `petsc` only in
// builds with PETSc).
#pragma once

#include "core/linear/linear_solver_controls.h"
#include "core/scene/config_map.h"

namespace fissure {

/// Reads `node` (keys `keys`) into `solver`, keeping the defaults it holds.
void read_linear_solver(const ConfigNode& node, const KeyTable& keys, LinearSolverControls& solver);

}  // namespace fissure
