#include "core/scene/read_linear_solver.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace fissure {

void read_linear_solver(const ConfigNode& node, const KeyTable& keys,
                        LinearSolverControls& solver) {
  using Type = LinearSolverControls::Type;
  solver.location = node.located_path();
  ConfigMap map(node, keys);
  constexpr std::string_view kTypes[] = {"auto", "direct", "pcg", "petsc"};
  std::optional<ConfigNode> type_node = map.optional("type");
  if (type_node) {
    if (auto type = type_node->choice(kTypes)) {
      solver.type = *type == "auto"     ? Type::Auto
                    : *type == "direct" ? Type::Direct
                    : *type == "pcg"    ? Type::Pcg
                                        : Type::Petsc;
#ifndef FISSURE_WITH_PETSC
      if (solver.type == Type::Petsc)
        type_node->error(
            "found 'petsc', but this build of Fissure has no PETSc; expected auto, direct or pcg");
#endif
    }
  }
  map.read("relative_tolerance", solver.relative_tolerance, quantity::dimensionless,
           Range::open(0, 1));
  if (auto limit = map.optional("max_iterations"))
    if (auto n = limit->integer(1, std::numeric_limits<int>::max()))
      solver.max_iterations = static_cast<int>(*n);
  if (auto options = map.optional("petsc_options")) {
    solver.petsc_options_location = options->located_path();
    if (options->is_null() || options->is_scalar())
      solver.petsc_options = std::string(options->text());
    else
      options->error(
          "found " + options->found() +
          "; expected a string of PETSc options, such as \"-ksp_type cg -pc_type gamg\"");
    if (!solver.petsc_options.empty() && (solver.type == Type::Direct || solver.type == Type::Pcg))
      options->error_at_key("found PETSc options with solver type '" +
                            std::string(solver.type == Type::Direct ? "direct" : "pcg") +
                            "', which does not use them; expected type petsc or auto, or no "
                            "petsc_options");
  }
  if (std::ranges::find(keys.keys, "refinement") == keys.keys.end()) return;
  if (auto refinement = map.optional("refinement")) {
    constexpr std::string_view kRefinements[] = {"auto", "always", "never"};
    if (auto r = refinement->choice(kRefinements))
      solver.refinement = *r == "auto"     ? LinearSolverControls::Refinement::Auto
                          : *r == "always" ? LinearSolverControls::Refinement::Always
                                           : LinearSolverControls::Refinement::Never;
    if (solver.type == Type::Petsc || solver.type == Type::Pcg)
      refinement->error_at_key(
          "found refinement with solver type '" +
          std::string(solver.type == Type::Petsc ? "petsc" : "pcg") +
          "', whose Krylov solvers do not refine; expected type direct or auto (for MUMPS "
          "through petsc_options, its own -mat_mumps_icntl_10)");
  }
}

}  // namespace fissure
