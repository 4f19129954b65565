// Cubic-law fracture network flow as a Fissure process (theory.md 3), alone
// or coupled with the block mechanics through its flow.hm section
// (hm_coupling.h; theory.md 3.5, 6). One flow update over [t0, t1]:
//   1. (coupled) wall positions and contact forces of the mechanics ->
//      hydraulic apertures at both ends of every segment;
//   2. cubic-law conductances with Iwai's wedge aperture (apertures.h), with
//      the viscosity of the water's temperature when a thermal process
//      writes it (segment_viscosity.h);
//   3. boundary conditions and wells at the update's time;
//   4. steady: T p* = q (steady_solver.h); transient: S dp*/dt + T p* = r with
//      storage from the fluid compressibility and the aperture change,
//      integrated implicitly with the flow's own (sub-)steps
//      (transient_integrator.h);
//   5. (coupled) the new pressures as loads on the block edges, for the
//      next mechanics steps;
//   6. (tied to a continuum) the flows its mouths give the continuum
//      (flow_ties.h).
// How often it updates is the coupling's business (coupling/splitting.h): by
// default after every mechanics step, or once per coupling interval, the
// pressure loads staying frozen in between.
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include <optional>

#include "core/process/process.h"
#include "flow/cubic_law/flow_controls.h"
#include "flow/cubic_law/flow_results.h"
#include "flow/cubic_law/flow_ties.h"
#include "flow/cubic_law/segment_viscosity.h"
#include "flow/hm/hm_coupling.h"
#include "flow/network/fluid.h"
#include "flow/network/steady_solver.h"
#include "flow/network/transient_integrator.h"

namespace fissure::flow {

class CubicLawProcess final : public Process {
 public:
  explicit CubicLawProcess(const Scene& scene);

  std::string name() const override { return "flow"; }
  std::vector<std::string> reads() const override;
  std::vector<std::string> writes() const override;
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass& state) const override;
  StepReport advance(RockMass& state, double t, double dt) override;
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override;
  /// The pressure at each monitor (m.p).
  const MonitorSource* monitors() const override { return &monitors_; }
  /// The flow state on the fracture network in each frame.
  ResultsPart* results() override { return &results_; }
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass&) const override { return nlohmann::json::object(); }
  void save(CheckpointWriter& out, const RockMass& state) const override;
  void restore(CheckpointReader& in, RockMass& state) override;

 private:
  void build_network(RockMass& state);
  void update_apertures(const RockMass& state);
  /// Advances the pressures to t1; Retry with half the step and what made
  /// the result impossible (nothing committed then), or Ok.
  StepReport update_flow(RockMass& state, double t0, double t1);
  /// The scene's conditions at t, and the ties' exchanges.
  NodeConditions conditions_at(const RockMass& state, double t) const;
  /// Per node, the fluid volume a unit pressure rise adds at fixed total
  /// stress (m^2/Pa; 0 without flow.hm).
  std::vector<double> node_compliances(const FractureGraph& graph) const;
  void publish(RockMass& state, const std::vector<double>& potential);
  /// Potentials p* of the node pressures (theory.md 3.1).
  std::vector<double> potentials(const FractureGraph& g, const std::vector<double>& pressure) const;
  /// What save() writes (Self and State const) and restore() reads
  /// (core/io/checkpoint.h).
  template <class Self, class State, class Archive>
  static void checkpoint(Self& self, State& state, Archive& a);

  FlowControls c_;
  FluidProperties fluid_;
  Vec2 gravity_;
  ApertureLimits limits_;
  std::optional<HmCoupling> hm_;  ///< with flow.hm: apertures from the blocks, loads on them
  double model_size_ = 1;

  /// Where the network was cut: its node positions and the blocks'
  /// vertices then (their initial vertices when the flow starts, which an
  /// initial stage resets afterwards; the walls are followed from here).
  std::vector<Vec2> reference_;
  BlockReference block_reference_;
  std::vector<int> well_nodes_;
  std::vector<SegmentWalls> walls_;
  std::vector<double> e_a_, e_b_, length_, conductance_, volume_;
  /// With a fluid temperature field: mu(T) per segment (Pa s).
  SegmentViscosity segment_viscosity_;
  std::vector<double> viscosity_;
  /// Per node, the pressure change published at the last update (Pa): the
  /// part of the next aperture change that answers it is already stored.
  std::vector<double> applied_change_;
  FlowTies ties_;  ///< the mouths on a continuum interface
  /// Per tied interface, the flow its mouths give the continuum (m^2/s).
  std::vector<std::pair<std::string, double>> interface_outflow_;
  bool order_checked_ = false;  ///< the first advance checked coupling.order
  std::unique_ptr<SteadySolver> steady_;
  std::unique_ptr<TransientIntegrator> integrator_;

  struct Counters {
    long updates = 0;
    double seconds = 0, balance_error = 0, explicit_limit = 0;
    int isolated_nodes = 0, dead_end_nodes = 0, unknowns = 0;
    /// The extremes of every pressure published since the start (Pa).
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
  } counters_;
  PressureMonitors monitors_;
  FlowResults results_;
  nlohmann::json network_;  ///< network summary (set by initialize)
  std::vector<double>
      boundary_flow_;  ///< per condition: inflow over its nodes (m^2/s), last update
  double p_min_ = 0, p_max_ = 0;
};

}  // namespace fissure::flow
