// Controls of a linear solver back end, shared by every process that solves
// a linear system (its section's `solver` map).
#pragma once

#include <string>

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
};

}  // namespace fissure
