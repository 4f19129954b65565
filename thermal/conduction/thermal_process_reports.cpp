// What the thermal process reports (thermal_process.h): node positions and
// monitor temperatures, summary.json's statistics and energy balance.
#include <limits>

#include "thermal/conduction/thermal_process.h"

namespace fissure::thermal {

std::vector<Vec2> ThermalProcess::node_positions(const RockMass& state) const {
  const std::vector<BlockMap> maps = block_maps(state.blocks, reference_);
  std::vector<Vec2> x(mesh_.nodes.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = maps[mesh_.node_block[i]](mesh_.nodes[i]);
  return x;
}

double ThermalProcess::temperature_at(const RockMass&, int point) const {
  if (s_.temperature.empty() || point >= static_cast<int>(monitor_places_.size()) ||
      monitor_places_[point].triangle < 0)
    return std::numeric_limits<double>::quiet_NaN();
  const ThermalMesh::Place& place = monitor_places_[point];
  const auto& tri = mesh_.triangles[place.triangle];
  double value = 0;
  for (int k = 0; k < 3; ++k) value += place.weights[k] * s_.temperature[tri[k]];
  return value;
}

nlohmann::json ThermalProcess::statistics() const {
  nlohmann::json j;
  j["mesh"] = {{"nodes", mesh_.n_nodes()},
               {"triangles", mesh_.n_triangles()},
               {"estimated_triangles", counters_.estimated_elements},
               {"seconds", counters_.mesh_seconds}};
  j["unknowns"] = n_dofs_;
  j["scheme"] = c_.scheme == ThermalControls::Scheme::Bdf2 ? "bdf2" : "backward_euler";
  j["capacity"] = c_.lumped_capacity ? "lumped" : "consistent";
  j["joints"] = c_.perfect_contact ? "perfect" : "conductance";
  j["steps"] = counters_.steps;
  j["smallest_step"] = counters_.smallest_step;
  j["largest_step"] = counters_.largest_step;
  j["largest_temperature_change"] = counters_.largest_change;
  if (step_control_.enabled())
    j["adaptive_step"] = {{"max_temperature_change", step_control_.max_change},
                          {"accepted_steps", counters_.steps},
                          {"rejected_steps", counters_.rejected_steps}};
  if (fluid_ && fluid_->built()) {
    const FractureConvection& f = fluid_->settings();
    j["fracture_fluid"] = {{"nodes", fluid_->n_nodes()},
                           {"pieces", fluid_->grid().pieces.size()},
                           {"own_unknowns", n_unknowns_ - n_dofs_},
                           {"nusselt", f.wall_temperature ? nlohmann::json("wall_temperature")
                                                          : nlohmann::json(f.nusselt)},
                           {"largest_flux", fluid_->largest_flux()},
                           {"segments_without_walls", fluid_->segments_without_walls()}};
  }
  j["system_builds"] = counters_.system_builds;
  j["factorizations"] = solver_.factorizations();
  j["solves"] = solver_.solves();
  j["factorization_seconds"] = solver_.factor_seconds();
  j["solve_seconds"] = solver_.solve_seconds();
  j["step_seconds"] = counters_.step_seconds;
  return j;
}

nlohmann::json ThermalProcess::energy(const RockMass&) const {
  if (s_.temperature.empty()) return nlohmann::json::object();
  const EnergyBalance& b = s_.balance;
  nlohmann::json heat = {{"stored", b.stored},
                         {"supplied_by_sources", b.supplied},
                         {"through_boundaries", b.boundary},
                         {"residual", b.residual()}};
  // BDF2 balances its time difference, not the stored change: the residual
  // holds the correction (thermal_state.h, docs/thermal.md 5), reported
  // beside it; with backward Euler it is 0.
  const bool bdf2 = c_.scheme == ThermalControls::Scheme::Bdf2;
  if (bdf2) heat["bdf2_correction"] = b.bdf2_correction;
  if (fluid_) {
    // The rock's `stored` holds what the water gave it (exchanged); the
    // residual is of rock and water together.
    heat["fracture_fluid"] = {{"stored", b.fluid.stored},
                              {"advected_in", b.fluid.advected_in},
                              {"advected_out", b.fluid.advected_out},
                              {"exchanged_with_rock", b.fluid.exchanged}};
    if (bdf2) heat["fracture_fluid"]["bdf2_correction"] = b.fluid.bdf2_correction;
  }
  return {{"heat", heat}};
}

void TemperatureMonitors::values(const RockMass& state, int point, std::span<double> out) const {
  out[0] = process_.temperature_at(state, point);
}

std::string TemperatureMonitors::why_missing(const RockMass& state, int point,
                                             std::string_view) const {
  return point < static_cast<int>(state.points.size()) && state.points[point].block < 0
             ? "is fixed in space outside the blocks (no temperature)"
             : "has no temperature";
}

}  // namespace fissure::thermal
