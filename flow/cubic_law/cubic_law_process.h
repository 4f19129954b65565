// Cubic-law fracture network flow as a Fissure process (theory.md 3), alone
// (physics: [flow]) or coupled with the block mechanics (physics: [mechanics,
// flow]; theory.md 3.5, 6). One flow update over [t_flow, t]:
//   1. (coupled) wall positions and contact forces of the mechanics ->
//      hydraulic apertures at both ends of every segment (hm_apertures.h);
//   2. cubic-law conductances with Iwai's wedge aperture (apertures.h);
//   3. boundary conditions and wells at the update's time;
//   4. steady: T p* = q (steady_solver.h); transient: S dp*/dt + T p* = r with
//      storage from the fluid compressibility and the aperture change,
//      integrated implicitly with the flow's own (sub-)steps
//      (transient_integrator.h);
//   5. (coupled) the new pressures as loads on the block edges
//      (pressure_loads.h), for the next mechanics steps.
// Coupling scheme: Lie splitting, mechanics then flow (theory.md 6.1). With
// flow.hm.coupling_interval > 0 the flow is updated once per interval and the
// pressure loads stay frozen in between; with 0, after every mechanics step.
#pragma once

#include <memory>
#include <vector>

#include "core/process/process.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"
#include "flow/network/fluid.h"
#include "flow/network/steady_solver.h"
#include "flow/network/transient_integrator.h"

namespace fissure::flow {

class CubicLawProcess final : public Process {
 public:
  explicit CubicLawProcess(const Scene& scene);

  std::string name() const override { return "flow"; }
  std::vector<Field> reads() const override;
  std::vector<Field> writes() const override;
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass& state) const override;
  StepReport advance(RockMass& state, double t, double dt) override;
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass&) const override { return nlohmann::json::object(); }

 private:
  void build_network(RockMass& state);
  void update_apertures(const RockMass& state);
  void update_flow(RockMass& state, double t0, double t1);
  NodeConditions conditions_at(const FractureGraph& graph, double t) const;
  void publish(RockMass& state, const std::vector<double>& potential);

  FlowControls c_;
  FluidProperties fluid_;
  Vec2 gravity_;
  bool coupled_ = false;
  double end_time_ = 0;
  double model_size_ = 1;
  HmApertureLaw law_;

  std::vector<Vec2> reference_;  ///< node positions at t = 0
  std::vector<int> well_nodes_;
  std::vector<SegmentWalls> walls_;
  std::vector<double> e_a_, e_b_, length_, conductance_, volume_;
  std::unique_ptr<SteadySolver> steady_;
  std::unique_ptr<TransientIntegrator> integrator_;
  double t_flow_ = 0;

  struct Counters {
    long updates = 0, skipped = 0;
    double seconds = 0, balance_error = 0, explicit_limit = 0;
    int isolated_nodes = 0, dead_end_nodes = 0, unknowns = 0;
  } counters_;
  WallState wall_state_;
  nlohmann::json network_;  ///< network summary (set by initialize)
  std::vector<double>
      boundary_flow_;  ///< per condition: inflow over its nodes (m^2/s), last update
  double p_min_ = 0, p_max_ = 0;
};

}  // namespace fissure::flow
