// Controls of a linear solver back end, shared by every process that solves
// a linear system (its section's `solver` map).
#pragma once

#include <string>

#include "core/base/errors.h"

namespace fissure {

struct LinearSolverControls {
  enum class Type { Auto, Direct, Pcg, Petsc };
  Type type = Type::Auto;
  double relative_tolerance = 1e-10;  ///< iterative solvers
  int max_iterations = 2000;          ///< iterative solvers
  std::string petsc_options;          ///< e.g. "-ksp_type cg -pc_type gamg"
  /// "file:line:column: path" of the scene's petsc_options, for PETSc's errors.
  std::string petsc_options_location;
  /// "file:line:column: path" of the scene's `solver` map; empty when the
  /// scene leaves the solver to its default. A system that cannot be solved
  /// before the first step is a scene problem reported there.
  std::string location;
  /// Iterative refinement of a direct solver's solves, where its section
  /// reads `refinement` (the continuum's): Auto lets a check of each new
  /// factor decide (continuum/poroelasticity/continuum_linear_solver.cpp),
  /// Always refines every solve, Never checks and refines nothing.
  enum class Refinement { Auto, Always, Never };
  Refinement refinement = Refinement::Auto;
};

/// A system that cannot be solved before the first step, as the scene
/// problem it is: at the scene's `solver` map (controls.location), else at
/// `fallback` (the mesh, the network). A message the solver located there
/// already is kept as it is.
inline SceneError unsolvable_at_start(const LinearSolverControls& controls,
                                      const std::string& fallback, const SolverError& e) {
  const std::string& where = controls.location.empty() ? fallback : controls.location;
  const std::string what = e.what();
  return SceneError(what.starts_with(where + ": ") ? what : where + ": " + what);
}

}  // namespace fissure
