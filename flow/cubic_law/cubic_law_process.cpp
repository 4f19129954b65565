#include "flow/cubic_law/cubic_law_process.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/process/exchanged_values.h"
#include "flow/cubic_law/flow_exchanged_fields.h"
#include "flow/network/boundary_conditions.h"
#include "flow/network/read_fluid.h"
#include "flow/network/transient_system.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fields/pressure_loads.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

namespace {

/// Heads are written when the flow has gravity (docs/flow.md 2).
HeadDefinition heads(const FlowControls& c, const Scene& scene) {
  if (!c.gravity) return {};
  return {c.fluid.density, scene.gravity};
}

/// The wells, marked on the pictures.
PointMarkers well_markers(const FlowControls& c) {
  PointMarkers wells{"flow_wells", "well", {}, {}};
  for (const FlowWell& w : c.wells) {
    wells.names.push_back(w.name);
    wells.points.push_back(w.point);
  }
  return wells;
}

}  // namespace

CubicLawProcess::CubicLawProcess(const Scene& scene)
    : c_(flow_controls(scene)),
      fluid_(c_.fluid),
      gravity_(c_.gravity ? Vec2(scene.gravity) : Vec2::Zero()),
      limits_{c_.residual_aperture, c_.maximum_aperture},
      results_(heads(c_, scene), well_markers(c_)) {
  if (c_.hm)
    hm_.emplace(HmApertureLaw{c_.hm->normal_stiffness, c_.hm->dilation_angle, c_.hm->dilation_limit,
                              limits_},
                scene.joints);
  steady_ = std::make_unique<SteadySolver>(c_.solver);
  if (c_.transient) integrator_ = std::make_unique<TransientIntegrator>(*c_.transient, c_.solver);
}

std::vector<std::string> CubicLawProcess::reads() const {
  std::vector<std::string> fields;
  if (hm_) fields = {std::string(block_fields::geometry), std::string(kContacts.name)};
  if (c_.network == FlowControls::NetworkSource::RockMass) fields.emplace_back(kFractureGraph.name);
  if (!ties_.empty()) fields.emplace_back(kContinuumInterfaces.name);
  fields.emplace_back(kFractureFlow.name);
  // The water's temperature when a thermal process writes it (theory.md 6.3).
  fields.emplace_back(kFractureFluidTemperature.name);
  return fields;
}

std::vector<std::string> CubicLawProcess::writes() const {
  std::vector<std::string> fields = kFlowSection.provided_fields();
  if (hm_) fields.emplace_back(kPressureLoads.name);
  if (!ties_.empty()) fields.emplace_back(kContinuumInterfaceLoads.name);
  return fields;
}

double CubicLawProcess::proposed_dt(const RockMass&) const {
  // Coupled: the mechanics sets the step, the flow sub-cycles or waits for
  // its coupling interval. Alone: the flow's own step (transient) or one
  // step to the next output (steady, CVODE's adaptive steps).
  if (!hm_ && c_.transient && c_.transient->time_step > 0) return c_.transient->time_step;
  return std::numeric_limits<double>::infinity();
}

NodeConditions CubicLawProcess::conditions_at(const RockMass& state, double t) const {
  const FractureGraph& g = state.fields.get(kFractureGraph);
  NodeConditions nc =
      resolve_conditions(g, c_.conditions, c_.wells, well_nodes_, fluid_, gravity_, t);
  if (!ties_.empty()) ties_.add_exchanges(state, nc);
  return nc;
}

std::vector<double> CubicLawProcess::node_compliances(const FractureGraph& g) const {
  if (!hm_) return std::vector<double>(g.n_nodes(), 0.0);
  // Shared by the segment's end nodes like its volume (node_volumes).
  const WallState& w = hm_->wall_state();
  return node_volumes(g, length_, w.compliance_a, w.compliance_b);
}

void CubicLawProcess::update_apertures(const RockMass& state) {
  const FractureGraph& g = state.fields.get(kFractureGraph);
  const int m = g.n_segments();
  if (hm_) {
    hm_->apertures(g, reference_, block_reference_, state, walls_, e_a_, e_b_);
  } else {
    // A rigid network: the walls stay where they are, the apertures are e0.
    walls_ = segment_walls(g, reference_, std::vector<BlockMap>(state.blocks.size()));
    e_a_.resize(m);
    e_b_.resize(m);
    for (int s = 0; s < m; ++s) e_a_[s] = e_b_[s] = clip_aperture(g.segments[s].aperture, limits_);
  }
  const std::vector<double>* temperature = state.fields.find(kFractureFluidTemperature);
  if (temperature) segment_viscosity_.update(g, *temperature, viscosity_);
  length_.resize(m);
  conductance_.resize(m);
  for (int s = 0; s < m; ++s) {
    const SegmentWalls& w = walls_[s];
    length_[s] = 0.5 * ((w.left_b - w.left_a).norm() + (w.right_b - w.right_a).norm());
    conductance_[s] = segment_conductance(e_a_[s], e_b_[s], length_[s],
                                          temperature ? viscosity_[s] : fluid_.viscosity);
  }
}

void CubicLawProcess::initialize(RockMass& state) {
  // Also called again after an initial stage: everything starts from here.
  counters_ = {};
  order_checked_ = false;
  segment_viscosity_ = {};
  check_fluid(fluid_);
  build_network(state);
  const FractureGraph& g = state.fields.get(kFractureGraph);
  update_apertures(state);

  // Initial pressure: uniform, or hydrostatic for a head (p* = rho |g| h).
  std::vector<double>& pressure = state.fields.get_or_add(kFractureFlow).pressure;
  pressure.assign(g.n_nodes(), c_.initial_pressure);
  if (c_.initial_head)
    for (int v = 0; v < g.n_nodes(); ++v)
      pressure[v] = fluid_.density * gravity_.norm() * *c_.initial_head +
                    hydrostatic_offset(fluid_, gravity_, g.nodes[v]);
  ties_ = {};
  const NodeConditions nc = conditions_at(state, state.time);
  // The mouths on a continuum interface (published: the continuum came first).
  ties_ = FlowTies::find(g, nc, state);
  if (!ties_.empty()) ties_.give_none(state);
  interface_outflow_ = ties_.outflows(state);
  for (int v = 0; v < g.n_nodes(); ++v)
    if (nc.is_fixed(v)) pressure[v] = nc.fixed_pressure[v];

  // A flow path must join the pressure boundaries (bad input, not a singular matrix).
  const NetworkTopology topo = reduce_network(g, conductance_, nc, false);
  check_pressure_boundaries_connected(g, c_.conditions, topo.component);

  volume_ = node_volumes(g, length_, e_a_, e_b_);
  // The pressure change the block walls have not felt yet: all of it, unless
  // the walls already carry these pressures (initialized again after an
  // initial stage, which settled the blocks under them).
  applied_change_ = pressure;
  if (state.fields.find(kPressureLoads))
    std::fill(applied_change_.begin(), applied_change_.end(), 0.0);
  static const char* sources[] = {"blocks", "traces", "rock_mass"};
  network_ = {{"source", sources[static_cast<int>(c_.network)]},
              {"nodes", g.n_nodes()},
              {"segments", g.n_segments()},
              {"components", topo.n_components}};
  if (!ties_.empty()) network_["tied_nodes"] = ties_.size();
  for (const auto& [name, nodes] : g.boundary_nodes) network_["boundaries"][name] = nodes.size();
  if (!c_.transient) {
    // A system that cannot be solved before the first step follows from the
    // scene: located at the solver it chose, else at the network.
    StepReport report;
    try {
      report = update_flow(state, state.time, state.time);
    } catch (const SolverError& e) {
      throw unsolvable_at_start(c_.solver, c_.network_path, e);
    }
    // No smaller step to retry with: the scene is wrong.
    FISSURE_CHECK(report.status == StepReport::Status::Ok, DivergenceError,
                  "flow: the initial steady state is impossible: " << report.reason);
  } else {
    publish(state, potentials(g, pressure));
  }
}

namespace {

/// "pressure nan at fracture node 12 (x, y)" for the first pressure that is
/// not finite or beyond what any rock holds (the largest pressure a scene
/// may give, 1e12 Pa); "" if none.
std::string impossible_pressure(const FractureGraph& g, const std::vector<double>& pressure) {
  for (std::size_t v = 0; v < pressure.size(); ++v)
    if (!(std::abs(pressure[v]) <= quantity::pressure.largest))
      return fmt::format("pressure {:g} Pa at fracture node {} ({:g}, {:g}) m, beyond {:g} Pa",
                         pressure[v], v, g.nodes[v].x(), g.nodes[v].y(),
                         quantity::pressure.largest);
  return {};
}

}  // namespace

StepReport CubicLawProcess::update_flow(RockMass& state, double t0, double t1) {
  const Stopwatch clock;
  const FractureGraph& g = state.fields.get(kFractureGraph);
  std::vector<double>& pressure = state.fields.get(kFractureFlow).pressure;
  const int n = g.n_nodes();
  // Nothing committed; a smaller step may help (a closing joint squeezing
  // its water faster than the step resolves).
  auto impossible = [&](std::string why) {
    return StepReport{StepReport::Status::Retry, 0.5 * (t1 - t0), std::move(why)};
  };
  if (!c_.transient) {
    const NodeConditions nc = conditions_at(state, t1);
    const NetworkSolution sol = steady_->solve(g, conductance_, nc, fluid_, gravity_, pressure);
    if (std::string bad = impossible_pressure(g, sol.pressure); !bad.empty())
      return impossible(bad);
    pressure = sol.pressure;
    if (!ties_.empty()) ties_.give(state, nc, pressure);
    counters_.balance_error = std::max(counters_.balance_error, sol.balance_error);
    counters_.isolated_nodes = sol.n_isolated_nodes;
    counters_.dead_end_nodes = sol.n_dead_end_nodes;
    counters_.unknowns = sol.n_unknowns;
  } else if (t1 > t0) {
    // Storage of the mean volume, and the aperture change as a source
    // (UDEC domain form, theory.md 3.4: V/K_f dp/dt = Q - dV/dt).
    const std::vector<double> v1 = node_volumes(g, length_, e_a_, e_b_);
    std::vector<double> v_mean(n);
    for (int v = 0; v < n; ++v) v_mean[v] = 0.5 * (volume_[v] + v1[v]);
    TransientSystem sys;
    build_transient_system(
        g, conductance_, v_mean, fluid_, gravity_,
        [this, &state](double t) { return conditions_at(state, t); }, t1, sys);
    // Coupled: the fixed-stress split (docs/flow.md 7; Kim, Tchelepi & Juanes
    // 2011). The joints' compliance at fixed total stress, C_i (m^2/Pa),
    // stores fluid as the pressure changes in this update; the aperture
    // change the mechanics made answers both the total stress and the
    // pressure loads of the last update, whose part C_i dp_last is taken out
    // (it is stored by that update's C_i). Without it the loop
    // pressure -> opening -> pressure is explicit, with the gain
    // K_f / (k_n e) (2200 for 50 um joints, k_n = 2e10 Pa/m), and diverges.
    const std::vector<double> compliance = node_compliances(g);
    for (int i = 0; i < sys.n(); ++i) {
      const int v = sys.network.node_of_unknown[i];
      sys.storage[i] += compliance[v];
      sys.extra[i] = -(v1[v] - volume_[v] - compliance[v] * applied_change_[v]) / (t1 - t0);
    }
    Eigen::VectorXd x(sys.n());
    for (int i = 0; i < sys.n(); ++i) {
      const int v = sys.network.node_of_unknown[i];
      x[i] = pressure[v] - sys.offset[v];
    }
    integrator_->network_changed();
    integrator_->advance(sys, x, t0, t1 - t0);
    counters_.explicit_limit = integrator_->last_explicit_limit();
    counters_.unknowns = sys.n();
    const NodeConditions nc = conditions_at(state, t1);
    std::vector<double> next = pressure;
    for (int v = 0; v < n; ++v)
      if (nc.is_fixed(v)) next[v] = nc.fixed_pressure[v];
    for (int i = 0; i < sys.n(); ++i)
      next[sys.network.node_of_unknown[i]] = x[i] + sys.offset[sys.network.node_of_unknown[i]];
    if (std::string bad = impossible_pressure(g, next); !bad.empty()) return impossible(bad);
    for (int v = 0; v < n; ++v) applied_change_[v] = next[v] - pressure[v];
    pressure = std::move(next);
    // The flows at the update's end (exact with one implicit step per update).
    if (!ties_.empty()) ties_.give(state, nc, pressure);
    volume_ = v1;
  }
  publish(state, potentials(g, pressure));
  interface_outflow_ = ties_.outflows(state);
  // Is the water still the correlation's liquid at the new pressures?
  if (const std::vector<double>* temperature = state.fields.find(kFractureFluidTemperature))
    segment_viscosity_.check_state(g, *temperature, pressure);
  ++counters_.updates;
  counters_.seconds += clock.seconds();
  return {};
}

void CubicLawProcess::publish(RockMass& state, const std::vector<double>& potential) {
  const FractureGraph& g = state.fields.get(kFractureGraph);
  FractureFlowState& flow = state.fields.get(kFractureFlow);
  flow.aperture_a = e_a_;
  flow.aperture_b = e_b_;
  segment_fluxes(g, conductance_, potential, flow.flux);
  // Inflow from outside per condition (the sum over its nodes; > 0 into the network).
  std::vector<double> inflow;
  node_inflows(g, flow.flux, inflow);
  boundary_flow_.assign(c_.conditions.size(), 0.0);
  for (std::size_t k = 0; k < c_.conditions.size(); ++k) {
    const auto it = g.boundary_nodes.find(c_.conditions[k].boundary);
    if (it != g.boundary_nodes.end())
      for (int v : it->second) boundary_flow_[k] += inflow[v];
  }
  if (!flow.pressure.empty()) {
    const auto [lo, hi] = std::minmax_element(flow.pressure.begin(), flow.pressure.end());
    p_min_ = *lo, p_max_ = *hi;
    counters_.lowest = std::min(counters_.lowest, p_min_);
    counters_.highest = std::max(counters_.highest, p_max_);
  }
  if (hm_) hm_->load_blocks(g, walls_, flow.pressure, state);
}

namespace {

/// Visits the exchanged values (flow_exchanged_fields.h) in one order.
template <class Visit>
void for_each_exchanged(auto& state, Visit&& visit) {
  if (auto* loads = state.fields.find(kPressureLoads))
    for (auto& l : *loads) {
      visit(kWallPressure, l.p_a);
      visit(kWallPressure, l.p_b);
    }
  if (auto* flow = state.fields.find(kFractureFlow)) {
    for (auto& v : flow->flux) visit(kSegmentFlux, v);
    for (auto* values : {&flow->aperture_a, &flow->aperture_b})
      for (auto& v : *values) visit(kSegmentAperture, v);
  }
  // The flows the network's mouths give a continuum (flow_ties.h).
  if (auto* loads = state.fields.find(kContinuumInterfaceLoads))
    for (auto& l : *loads)
      for (auto& q : l.fluid.values) visit(kTieFluidFlow, q);
}

}  // namespace

std::vector<ExchangedField> CubicLawProcess::exchanged_values(const RockMass& state) const {
  return gather_exchanged(state, kExchangedFields,
                          [](auto& s, auto&& visit) { for_each_exchanged(s, visit); });
}

void CubicLawProcess::set_exchanged_values(RockMass& state,
                                           std::span<const ExchangedField> values) {
  scatter_exchanged(state, values, [](auto& s, auto&& visit) { for_each_exchanged(s, visit); });
}

StepReport CubicLawProcess::advance(RockMass& state, double t, double dt) {
  if (!order_checked_ && ties_.empty()) {
    // The interfaces are published when the continuum initializes: a
    // network that found none at its own start but one now came first.
    FISSURE_CHECK(
        FlowTies::find(state.fields.get(kFractureGraph), conditions_at(state, t), state).empty(),
        CouplingOrderError, tied_before_continuum("flow", "its fracture network reaches"));
  }
  order_checked_ = true;
  update_apertures(state);
  StepReport report = update_flow(state, t, t + dt);
  if (report.status == StepReport::Status::Retry) report.reason = "flow: " + report.reason;
  return report;
}

std::vector<double> CubicLawProcess::potentials(const FractureGraph& g,
                                                const std::vector<double>& pressure) const {
  std::vector<double> potential(pressure.size());
  for (std::size_t v = 0; v < pressure.size(); ++v)
    potential[v] = pressure[v] - hydrostatic_offset(fluid_, gravity_, g.nodes[v]);
  return potential;
}

template <class Self, class State, class Archive>
void CubicLawProcess::checkpoint(Self& self, State& state, Archive& a) {
  a("pressure", state.fields.get(kFractureFlow).pressure);
  a("aperture_a", self.e_a_);
  a("aperture_b", self.e_b_);
  a("length", self.length_);
  a("conductance", self.conductance_);
  a("volume", self.volume_);
  a("applied_change", self.applied_change_);
  a.list("walls", self.walls_, [](auto& e, auto& w) {
    e("left_a", w.left_a);
    e("left_b", w.left_b);
    e("right_a", w.right_a);
    e("right_b", w.right_b);
    e("mechanical", w.mechanical);
  });
  auto c = a.section("counters");
  auto& n = self.counters_;  // const when writing
  c("updates", n.updates);
  c("seconds", n.seconds);
  c("balance_error", n.balance_error);
  c("explicit_limit", n.explicit_limit);
  c("isolated_nodes", n.isolated_nodes);
  c("dead_end_nodes", n.dead_end_nodes);
  c("unknowns", n.unknowns);
  c("lowest", n.lowest);
  c("highest", n.highest);
  SegmentViscosity::checkpoint(self.segment_viscosity_, a);
  auto steady = a.section("steady_solver");
  SteadySolver::checkpoint(const_like<Self>(*self.steady_), steady);
  if (self.integrator_) {
    auto transient = a.section("transient");
    TransientIntegrator::checkpoint(const_like<Self>(*self.integrator_), transient);
  }
}

void CubicLawProcess::save(CheckpointWriter& out, const RockMass& state) const {
  checkpoint(*this, state, out);
  if (!ties_.empty())  // the flows its mouths give the continuum
    out("interface_fluid_flows", ties_.values(state));
}

void CubicLawProcess::restore(CheckpointReader& in, RockMass& state) {
  checkpoint(*this, state, in);
  if (!ties_.empty()) {
    std::vector<double> flows;
    in("interface_fluid_flows", flows);
    ties_.set_values(state, flows);
    interface_outflow_ = ties_.outflows(state);
  }
  order_checked_ = true;
  const FractureGraph& g = state.fields.get(kFractureGraph);
  const std::vector<double>& pressure = state.fields.get(kFractureFlow).pressure;
  FISSURE_CHECK(static_cast<int>(pressure.size()) == g.n_nodes() &&
                    static_cast<int>(e_a_.size()) == g.n_segments(),
                IoError,
                "the checkpoint's fracture network (" << pressure.size() << " nodes) is not the "
                                                      << "scene's (" << g.n_nodes() << " nodes)");
  // Fluxes, boundary inflows and pressure loads follow from the pressures.
  publish(state, potentials(g, pressure));
}

nlohmann::json CubicLawProcess::statistics() const {
  nlohmann::json j;
  j["network"] = network_;
  j["coupling"] = hm_ ? "hm (apertures from the blocks, pressure loads on them)" : "none";
  // Which joint law the apertures follow, where some joint has a model.
  if (hm_ && hm_->laws().any_model()) j["aperture_laws"] = hm_->laws().segments_per_law();
  j["pressure"] = {{"min", p_min_}, {"max", p_max_}};
  if (counters_.lowest <= counters_.highest)
    j["pressure"]["run"] = {{"min", counters_.lowest}, {"max", counters_.highest}};
  for (std::size_t k = 0; k < c_.conditions.size(); ++k)
    j["boundary_inflow"][c_.conditions[k].boundary] =
        boundary_flow_.size() > k ? boundary_flow_[k] : 0.0;
  for (const auto& [name, q] : interface_outflow_) j["interface_outflow"][name] = q;
  j["flow_updates"] = counters_.updates;
  j["unknowns"] = counters_.unknowns;
  j["isolated_nodes"] = counters_.isolated_nodes;
  j["dead_end_nodes"] = counters_.dead_end_nodes;
  j["balance_error"] = counters_.balance_error;
  j["seconds"] = counters_.seconds;
  j["explicit_time_step_limit"] = counters_.explicit_limit;
  j["steady_solver"] = steady_->statistics();
  if (integrator_) j["transient"] = integrator_->statistics();
  if (segment_viscosity_.used()) j["viscosity"] = segment_viscosity_.statistics();
  if (!e_a_.empty()) {
    const auto [lo, hi] = std::minmax_element(e_a_.begin(), e_a_.end());
    const auto [lo_b, hi_b] = std::minmax_element(e_b_.begin(), e_b_.end());
    j["aperture"] = {{"min", std::min(*lo, *lo_b)}, {"max", std::max(*hi, *hi_b)}};
  }
  return j;
}

}  // namespace fissure::flow
