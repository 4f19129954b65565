#include "flow/hm/create_flow_process.h"

#include "flow/hm/flow_process.h"

namespace fissure::flow {

std::unique_ptr<Process> create_flow_process(const Scene& scene) {
  return std::make_unique<FlowProcess>(scene);
}

LinearSolverControls linear_controls(const FlowControls::Solver& s) {
  using In = FlowControls::Solver::Type;
  using Out = LinearSolverControls::Type;
  LinearSolverControls c;
  c.type = s.type == In::Direct  ? Out::Direct
           : s.type == In::Pcg   ? Out::Pcg
           : s.type == In::Petsc ? Out::Petsc
                                 : Out::Auto;
  c.relative_tolerance = s.relative_tolerance;
  c.max_iterations = s.max_iterations;
  c.petsc_options = s.petsc_options;
  return c;
}

}  // namespace fissure::flow
