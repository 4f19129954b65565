// Heat conduction in the blocks as a Fissure process (theory.md 4.1,
// docs/thermal.md). advance() takes one thermal step over [t, t + dt] in
// four named steps:
//   1. close_joints: (with mechanics) which joint faces are closed, from the
//      contacts; perfect contact merges the nodes of closed faces into one
//      unknown, a contact conductance couples them;
//   2. factor_system: the matrices on the blocks' reference geometry, and
//      the factor of a0 M / dt + K, reused while dt, the mesh and the closed
//      faces stay;
//   3. implicit_step: backward Euler, or variable-step BDF2
//      (a0 T1 - a1 T0 + a2 T-1 = dt (F - K T1), core/base/bdf2.h); with
//      thermal.max_temperature_change, a step whose largest nodal change
//      exceeds it is rejected (Retry, the state untouched) and the next
//      step adapts (temperature_step_control.h);
//   4. accept_step: the energy balance, then the blocks' mean temperature
//      change dT and, with each material's linear thermal expansion
//      alpha_T, their free thermal strain alpha_T dT for the mechanics
//      (kBlockThermalStrain).
// Its inner state (temperatures, the BDF2 history, the next step, the
// energy balance: thermal_state.h) is its own, behind save()/restore() like
// every process's; the shared state holds only what others read.
// With thermal.convection the fracture water's energy balance is solved in
// the same system (thermal/convection/fracture_fluid.h, docs/thermal.md 7),
// with the flow's fluxes (kFractureFlow), and its temperature per segment
// is written for the flow's viscosity (kFractureFluidTemperature).
// The mesh moves with its block: node positions for the output are the
// reference ones mapped by the block's affine motion (rockmass/block_motion.h).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <vector>

#include "core/io/monitor_source.h"
#include "core/io/results_part.h"
#include "core/process/process.h"
#include "rockmass/block_motion.h"
#include "thermal/conduction/conduction_matrices.h"
#include "thermal/conduction/conduction_solver.h"
#include "thermal/conduction/heat_sources.h"
#include "thermal/conduction/temperature_step_control.h"
#include "thermal/conduction/thermal_mesh.h"
#include "thermal/conduction/thermal_settings.h"
#include "thermal/conduction/thermal_state.h"
#include "thermal/conduction/thermal_ties.h"
#include "thermal/convection/fracture_fluid.h"

namespace fissure::thermal {

class ThermalProcess;

/// m.T: the temperature at a monitor (degC), interpolated on its block's mesh.
class TemperatureMonitors final : public MonitorSource {
 public:
  explicit TemperatureMonitors(const ThermalProcess& process) : process_(process) {}
  std::vector<MonitorColumn> columns() const override { return {{"T", 2, true}}; }
  void values(const RockMass& state, int point, std::span<double> out) const override;
  std::string why_missing(const RockMass& state, int point, std::string_view column) const override;

 private:
  const ThermalProcess& process_;
};

/// The block meshes and their temperatures in results.h5 / results.xdmf:
/// /mesh/thermal_triangles, per frame thermal/nodes (current positions) and
/// thermal/temperature, the "thermal" grid.
class ThermalResults final : public ResultsPart {
 public:
  explicit ThermalResults(const ThermalProcess& process) : process_(process) {}
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;

 private:
  const ThermalProcess& process_;
};

class ThermalProcess final : public Process {
 public:
  explicit ThermalProcess(const Scene& scene);

  std::string name() const override { return "thermal"; }
  std::vector<std::string> reads() const override;
  std::vector<std::string> writes() const override;
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass& state) const override;
  StepReport advance(RockMass& state, double t, double dt) override;
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override;
  const MonitorSource* monitors() const override { return &monitors_; }
  ResultsPart* results() override { return &results_; }
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass& state) const override;
  void save(CheckpointWriter& out, const RockMass& state) const override;
  void restore(CheckpointReader& in, RockMass& state) override;

  /// Its inner state: node temperatures, BDF2 history, energy balance.
  const ThermalState& inner_state() const { return s_; }
  /// Starts from these node temperatures (a verification's initial field),
  /// as if they had been there for a step; publishes the thermal strains.
  void set_temperature(RockMass& state, std::vector<double> temperature);
  const ThermalControls& controls() const { return c_; }
  const ThermalMesh& mesh() const { return mesh_; }
  /// The fracture water (thermal.convection), or null.
  const FractureFluid* fluid() const { return fluid_ ? &*fluid_ : nullptr; }
  /// Current node positions (the reference ones moved with their blocks).
  std::vector<Vec2> node_positions(const RockMass& state) const;
  /// The temperature at material point `point`; NaN when it is in no block.
  double temperature_at(const RockMass& state, int point) const;

 private:
  /// What one step works on, from close_joints to accept_step
  /// (thermal_process_step.cpp).
  struct Step;
  Step close_joints(RockMass& state);
  void factor_system(const RockMass& state, double dt, Step& step);
  void implicit_step(double t, Step& step);
  void accept_step(RockMass& state, Step& step);
  /// The energy terms of an accepted step into s_.balance.
  void account_energy(const Step& step);

  /// save() and restore(): Self is const ThermalProcess when writing.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);
  void resolve_conditions();
  /// Closed joint faces (per boundary edge) from the contacts, or all of them.
  std::vector<char> closed_faces(const RockMass& state) const;
  /// Numbering of the unknowns for these closed faces, and the matrices.
  void build_system(const std::vector<char>& closed);
  Eigen::VectorXd to_dofs(const std::vector<double>& node_values) const;
  /// Every node of an unknown gets the unknown's value: the
  /// capacity-weighted mean of its nodes (conserves the stored energy).
  void equalize(std::vector<double>& node_values) const;
  /// Per block, the area-weighted mean of the node values `t` (exact for P1).
  std::vector<double> block_means(const std::vector<double>& t) const;
  /// The blocks' mean temperature change (s_) and free thermal strain
  /// (kBlockThermalStrain), from the node temperatures.
  void publish(RockMass& state);
  /// With convection: the fluid grid on the flow's network, built once the
  /// network exists (its first call with one); true when it was built now.
  bool build_fluid(RockMass& state);
  /// The water's temperatures at the fluid nodes, unless `s` has them.
  void start_fluid();
  /// The step's matrix a0 / dt M + K, with the water's rows and columns.
  SparseMatrix step_matrix(double coefficient) const;

  ThermalControls c_;
  ThermalState s_;  ///< the inner state (thermal_state.h)
  TemperatureStepControl step_control_;
  bool with_mechanics_ = false;
  std::vector<NamedWall> walls_;  ///< the rock mass's excavations
  BlockReference reference_;
  ThermalMesh mesh_;
  ElementProperties props_;
  std::vector<int> source_block_;
  std::vector<NodalWeights> source_weights_;
  /// Per mesh boundary edge: its condition (index of c_.conditions), or -1.
  std::vector<int> edge_condition_;
  std::vector<double> block_area_, block_reference_temperature_;
  std::vector<double> node_mean_weight_;  ///< per node, A_t / 3 of its triangles (block_means)
  std::vector<char> built_closed_;        ///< the closed joint faces the system was built for
  std::vector<int> node_dof_;
  int n_dofs_ = 0;
  std::vector<bool> fixed_dof_;
  std::vector<int> fixed_condition_;  ///< per dof: the condition that fixes it (-1: none)
  ConductionMatrices matrices_;
  ConductionSolver solver_;
  std::optional<FractureFluid> fluid_;
  ThermalTies ties_;                ///< the blocks' edges tied to a continuum interface
  int n_unknowns_ = 0;              ///< the blocks' n_dofs_ and the water's own unknowns
  bool system_has_fluid_ = false;   ///< the numbering holds the water's unknowns
  double matrix_coefficient_ = -1;  ///< a0 / dt of the solver's matrix; < 0: none
  /// matrix_coefficient_ of a restored checkpoint, until the next step
  /// (advance); < 0: none.
  double restored_coefficient_ = -1;

  std::vector<ThermalMesh::Place> monitor_places_;

  struct Counters {
    long steps = 0, system_builds = 0;
    long rejected_steps = 0;                     ///< by thermal.max_temperature_change
    double smallest_step = 0, largest_step = 0;  ///< accepted, s (0: none yet)
    double largest_change = 0;                   ///< of an accepted step, K
    double mesh_seconds = 0, step_seconds = 0;
    double estimated_elements = 0;
  } counters_;
  TemperatureMonitors monitors_{*this};
  ThermalResults results_{*this};
};

}  // namespace fissure::thermal
