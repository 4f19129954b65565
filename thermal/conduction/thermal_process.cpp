#include "thermal/conduction/thermal_process.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <set>
#include <tuple>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure::thermal {

namespace {

/// The finest element at the sources, relative to the global size.
constexpr double kFinestRelativeSize = 1e-4;

/// Relative change of a0 / dt below which the factor is reused.
constexpr double kSameStep = 1e-12;

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double edge_length(const ThermalMesh& mesh, const BoundaryEdge& e) {
  return (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
}

}  // namespace

ThermalProcess::ThermalProcess(const Scene& scene)
    : c_(thermal_controls(scene)),
      step_control_{c_.max_temperature_change, c_.time_step},
      with_mechanics_(scene.has_physics("mechanics")) {
  // Scenes built in code may leave materials out: the defaults then.
  if (c_.materials.size() < scene.materials.size()) c_.materials.resize(scene.materials.size());
  if (const RockMassSpec* spec = scene.sections.find(kRockMassSpec))
    for (const ExcavationSpec& e : spec->excavations) walls_.push_back({e.name, e.vertices});
}

std::vector<std::string> ThermalProcess::reads() const {
  std::vector<std::string> fields = {std::string(block_fields::geometry)};
  if (with_mechanics_) fields.emplace_back(kContacts.name);
  return fields;
}

std::vector<std::string> ThermalProcess::writes() const {
  return {std::string(kBlockThermalStrain.name), std::string(kThermalState.name)};
}

double ThermalProcess::proposed_dt(const RockMass& state) const {
  if (!(c_.time_step > 0)) return std::numeric_limits<double>::infinity();
  if (step_control_.enabled())
    if (const ThermalState* s = state.fields.find(kThermalState); s && s->next_dt > 0)
      return s->next_dt;
  return c_.time_step;
}

void ThermalProcess::resolve_conditions() {
  edge_condition_.assign(mesh_.boundary_edges.size(), -1);
  for (int i = 0; i < static_cast<int>(c_.conditions.size()); ++i) {
    const ThermalCondition& condition = c_.conditions[i];
    const std::vector<int>* edges = mesh_.boundary(condition.boundary);
    if (!edges || edges->empty()) {
      std::string names;
      for (const auto& [name, list] : mesh_.boundaries)
        if (!list.empty()) names += (names.empty() ? "" : ", ") + name;
      throw SceneError(fmt::format(
          "{}: found boundary '{}', which has no exterior block edge; expected one of: {}",
          condition.path, condition.boundary, names));
    }
    for (const int e : *edges) {
      const int other = edge_condition_[e];
      if (other >= 0 && other != i)
        throw SceneError(fmt::format(
            "{}: found boundary '{}', which shares edges with boundary '{}' of the condition "
            "at {}; expected one condition on each part of the boundary",
            condition.path, condition.boundary, c_.conditions[other].boundary,
            c_.conditions[other].path));
      edge_condition_[e] = i;
    }
  }
}

std::vector<char> ThermalProcess::closed_faces(const RockMass& state) const {
  const std::vector<BoundaryEdge>& edges = mesh_.boundary_edges;
  std::vector<char> closed(edges.size(), 0);
  const std::vector<ContactRecord>* contacts =
      with_mechanics_ ? state.fields.find(kContacts) : nullptr;
  if (!contacts) {
    // No mechanics (or before its first step): coincident faces conduct.
    for (std::size_t e = 0; e < edges.size(); ++e) closed[e] = edges[e].partner >= 0;
    return closed;
  }
  // A face is closed while a contact between its two polygon edges is.
  std::set<std::tuple<int, int, int>> touching;  // (edge's block, its edge, other block)
  for (const ContactRecord& r : *contacts)
    if (r.state != ContactState::Open) touching.emplace(r.block_j, r.edge, r.block_i);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].partner < 0) continue;
    const BoundaryEdge &a = edges[e], &b = edges[a.partner];
    closed[e] = touching.count({a.block, a.polygon_edge, b.block}) ||
                touching.count({b.block, b.polygon_edge, a.block});
  }
  return closed;
}

void ThermalProcess::build_system(const std::vector<char>& closed) {
  const int n = mesh_.n_nodes();
  const std::vector<BoundaryEdge>& edges = mesh_.boundary_edges;
  // Perfect contact: the nodes of a closed face and its partner's are one
  // unknown (the same points: a -> b faces b' -> a').
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<EdgeTransfer> joints, convective;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!closed[e]) continue;
    const BoundaryEdge &a = edges[e], &b = edges[a.partner];
    if (c_.perfect_contact) {
      for (const auto& [x, y] : {std::pair{a.a, b.b}, std::pair{a.b, b.a}}) {
        const int rx = find_root(parent, x), ry = find_root(parent, y);
        if (rx != ry) parent[std::max(rx, ry)] = std::min(rx, ry);
      }
    } else if (c_.contact_conductance > 0) {
      joints.push_back({static_cast<int>(e), c_.contact_conductance});
    }
  }
  node_dof_.assign(n, -1);
  std::vector<int> root_dof(n, -1);
  n_dofs_ = 0;
  for (int i = 0; i < n; ++i) {
    const int r = find_root(parent, i);
    if (root_dof[r] < 0) root_dof[r] = n_dofs_++;
    node_dof_[i] = root_dof[r];
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k >= 0 && c_.conditions[k].type == ThermalCondition::Type::Convection)
      convective.push_back({static_cast<int>(e), c_.conditions[k].value});
  }
  matrices_ = conduction_matrices(mesh_, props_, node_dof_, n_dofs_, c_.lumped_capacity, joints,
                                  convective);
  fixed_dof_.assign(n_dofs_, false);
  fixed_condition_.assign(n_dofs_, -1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k < 0 || c_.conditions[k].type != ThermalCondition::Type::Temperature) continue;
    for (const int node : {edges[e].a, edges[e].b}) {
      fixed_dof_[node_dof_[node]] = true;
      fixed_condition_[node_dof_[node]] = k;
    }
  }
  built_closed_ = closed;
  matrix_coefficient_ = -1;
  ++counters_.system_builds;
}

Eigen::VectorXd ThermalProcess::to_dofs(const std::vector<double>& node_values) const {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n_dofs_), weight = Eigen::VectorXd::Zero(n_dofs_);
  for (std::size_t i = 0; i < node_values.size(); ++i) {
    sum[node_dof_[i]] += matrices_.node_capacity[i] * node_values[i];
    weight[node_dof_[i]] += matrices_.node_capacity[i];
  }
  return sum.cwiseQuotient(weight);
}

void ThermalProcess::equalize(std::vector<double>& node_values) const {
  const Eigen::VectorXd dofs = to_dofs(node_values);
  for (std::size_t i = 0; i < node_values.size(); ++i) node_values[i] = dofs[node_dof_[i]];
}

void ThermalProcess::initialize(RockMass& state) {
  Stopwatch clock;
  counters_ = {};
  reference_.assign(state.blocks.size(), {});
  Box all;
  double area = 0;
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    reference_[b] = state.blocks[b].polygon.vertices;
    all.extend(bounding_box(state.blocks[b].polygon));
    area += std::abs(state.blocks[b].section.area);
  }
  const SizeField size(c_, all.size().maxCoeff());
  // Refinement towards a point stops being representable well before
  // 1e-12 of the model (CGAL's circumcentres collapse): a floor far above.
  FISSURE_CHECK(
      size.at_sources() >= kFinestRelativeSize * size.global(), SceneError,
      fmt::format("{}: found elements of {:g} m at the sources and {:g} m elsewhere; "
                  "expected source_element_size at least element_size / {:g}",
                  c_.mesh_path, size.at_sources(), size.global(), 1 / kFinestRelativeSize));
  source_block_ = source_blocks(c_.sources, state.blocks);
  counters_.estimated_elements = size.estimate_elements(state.blocks);
  FISSURE_CHECK(counters_.estimated_elements <= c_.max_elements, SceneError,
                fmt::format("{}: the block meshes would have about {:.3g} triangles (element "
                            "size {:g} m, {:g} m at the sources, over {:.4g} m^2 of rock); "
                            "expected at most thermal.mesh.max_elements = {:.3g}: a larger "
                            "element_size, or a larger max_elements",
                            c_.mesh_path, counters_.estimated_elements, size.global(),
                            size.at_sources(), area, c_.max_elements));
  try {
    mesh_ = build_thermal_mesh(state, size, c_.sources, source_block_, walls_);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    throw SceneError(fmt::format("{}: cannot mesh the blocks: {}", c_.mesh_path, e.what()));
  }
  props_.conductivity.clear();
  props_.capacity.clear();
  for (const int b : mesh_.triangle_block) {
    const ThermalMaterial& m = c_.materials[state.blocks[b].material];
    props_.conductivity.push_back(m.conductivity);
    props_.capacity.push_back(m.heat_capacity);
  }
  source_weights_ = source_weights(c_.sources, source_block_, mesh_);
  resolve_conditions();

  // The initial field: uniform or a gradient (the boundary temperatures
  // apply from the first step on).
  ThermalState& s = state.fields.set(kThermalState, ThermalState{});
  s.temperature.resize(mesh_.n_nodes());
  for (int i = 0; i < mesh_.n_nodes(); ++i)
    s.temperature[i] =
        c_.initial_temperature + c_.gradient.dot(mesh_.nodes[i] - c_.reference_point);
  s.closed = closed_faces(state);
  build_system(s.closed);
  equalize(s.temperature);
  s.previous_temperature = s.temperature;

  // Each block's stress-free temperature: its mean initial temperature.
  block_area_.assign(state.blocks.size(), 0.0);
  for (int t = 0; t < mesh_.n_triangles(); ++t)
    block_area_[mesh_.triangle_block[t]] += mesh_.triangle_area[t];
  block_reference_temperature_ = block_means(s.temperature);
  publish(state);

  // Monitors: the triangle of their block that holds them, and the weights
  // (a monitor fixed in space: the triangle of any block that holds it at
  // the start, if one does; 1e-9: on a triangle's edge).
  monitor_places_.assign(state.points.size(), {});
  for (std::size_t p = 0; p < state.points.size(); ++p) {
    const MaterialPoint& point = state.points[p];
    monitor_places_[p] = mesh_.locate(point.current, point.block);
    if (point.block < 0 && !(monitor_places_[p].weights.minCoeff() >= -1e-9))
      monitor_places_[p] = {};
  }
  counters_.mesh_seconds = clock.seconds();
}

std::vector<double> ThermalProcess::block_means(const std::vector<double>& t) const {
  std::vector<double> mean(block_area_.size(), 0.0);
  for (int k = 0; k < mesh_.n_triangles(); ++k) {
    const auto& tri = mesh_.triangles[k];
    mean[mesh_.triangle_block[k]] +=
        mesh_.triangle_area[k] * (t[tri[0]] + t[tri[1]] + t[tri[2]]) / 3;
  }
  for (std::size_t b = 0; b < mean.size(); ++b) mean[b] /= block_area_[b];
  return mean;
}

void ThermalProcess::publish(RockMass& state) const {
  ThermalState& s = state.fields.get(kThermalState);
  s.block_temperature_change = block_means(s.temperature);
  std::vector<double> strain(s.block_temperature_change.size());
  for (std::size_t b = 0; b < strain.size(); ++b) {
    s.block_temperature_change[b] -= block_reference_temperature_[b];
    strain[b] =
        c_.materials[state.blocks[b].material].thermal_expansion * s.block_temperature_change[b];
  }
  state.fields.set(kBlockThermalStrain, std::move(strain));
}

StepReport ThermalProcess::advance(RockMass& state, double t, double dt) {
  Stopwatch clock;
  ThermalState& s = state.fields.get(kThermalState);
  const std::vector<char> closed = closed_faces(state);
  if (closed != built_closed_) build_system(closed);
  // The state changes only once the step is accepted (a Retry leaves it).
  std::vector<double> start = s.temperature;
  double previous_dt = s.previous_dt;
  if (closed != s.closed) {
    // Faces opened or closed: perfect contact regroups the unknowns (energy
    // kept), and BDF2 starts again from this state.
    equalize(start);
    previous_dt = 0;
  }
  // Backward Euler, or BDF2 with the step ratio w = dt / dt_previous:
  // a0 T1 - a1 T0 + a2 T-1 = dt (F - K T1).
  double a0 = 1, a1 = 1, a2 = 0;
  if (c_.scheme == ThermalControls::Scheme::Bdf2 && previous_dt > 0) {
    const double w = dt / previous_dt;
    a0 = (1 + 2 * w) / (1 + w);
    a1 = 1 + w;
    a2 = w * w / (1 + w);
  }
  // The factor is kept when a0 / dt changes by round-off only (a sub-cycled
  // interval summed from shorter steps): the step is then taken with the
  // factor's dt, 1e-12 relative from the asked one, and everything below
  // (loads, energy) uses that dt, so the balance stays exact.
  if (std::abs(a0 / dt - matrix_coefficient_) > kSameStep * (a0 / dt)) {
    solver_.set_matrix(SparseMatrix(a0 / dt * matrices_.capacity + matrices_.conductance),
                       fixed_dof_);
    matrix_coefficient_ = a0 / dt;
  }
  dt = a0 / matrix_coefficient_;
  const Eigen::VectorXd t0 = to_dofs(start);
  const Eigen::VectorXd tm = a2 != 0 ? to_dofs(s.previous_temperature) : t0;

  // Sources and conditions at t + dt: the flux and convective loads, the
  // fixed temperatures.
  std::vector<double> condition_value(c_.conditions.size());
  for (std::size_t k = 0; k < c_.conditions.size(); ++k) {
    const ThermalCondition& c = c_.conditions[k];
    condition_value[k] = c.type == ThermalCondition::Type::Convection
                             ? c.value * c.external_temperature_at(t + dt)
                             : c.value_at(t + dt);
  }
  Eigen::VectorXd source = Eigen::VectorXd::Zero(n_dofs_), load = Eigen::VectorXd::Zero(n_dofs_);
  for (std::size_t k = 0; k < c_.sources.size(); ++k) {
    const double power = c_.sources[k].power * c_.sources[k].factor.at(t + dt);
    for (const auto& [node, w] : source_weights_[k]) source[node_dof_[node]] += power * w;
  }
  const std::vector<BoundaryEdge>& edges = mesh_.boundary_edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k < 0) continue;
    if (c_.conditions[k].type == ThermalCondition::Type::Temperature) continue;
    const double half = edge_length(mesh_, edges[e]) / 2;  // int N ds
    const double q = condition_value[k];                   // W/m^2: the flux, or h T_ext
    load[node_dof_[edges[e].a]] += q * half;
    load[node_dof_[edges[e].b]] += q * half;
  }
  const Eigen::VectorXd rhs = matrices_.capacity * (a1 * t0 - a2 * tm) / dt + source + load;
  Eigen::VectorXd t1 = t0;
  for (int d = 0; d < n_dofs_; ++d)
    if (fixed_dof_[d]) t1[d] = condition_value[fixed_condition_[d]];
  solver_.solve(rhs, t1);
  FISSURE_CHECK(t1.allFinite(), DivergenceError,
                "thermal: non-finite temperatures at t = " << t + dt << " s");

  // The change the step caused: the fixed temperatures' is prescribed,
  // whatever the step, and takes no part.
  double change = 0;
  for (int d = 0; d < n_dofs_; ++d)
    if (!fixed_dof_[d]) change = std::max(change, std::abs(t1[d] - t0[d]));
  if (!step_control_.accepts(change)) {
    ++counters_.rejected_steps;
    counters_.step_seconds += clock.seconds();
    return {StepReport::Status::Retry, step_control_.retry_step(dt, change),
            fmt::format("thermal: the step of {:g} s changed a temperature by {:g} K, more "
                        "than thermal.max_temperature_change = {:g} K",
                        dt, change, step_control_.max_change)};
  }

  // Energy (J/m): summing every row of the step's equations, conduction and
  // joints cancel (K 1 = 0 without the convective part), so the stored
  // change is what the sources, the boundary loads, the convective
  // exchange and the fixed temperatures' reactions bring in.
  double boundary = load.sum() + solver_.fixed_reaction(rhs, t1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k >= 0 && c_.conditions[k].type == ThermalCondition::Type::Convection)
      boundary -= c_.conditions[k].value * edge_length(mesh_, edges[e]) / 2 *
                  (t1[node_dof_[edges[e].a]] + t1[node_dof_[edges[e].b]]);
  }
  EnergyBalance& b = s.balance;
  b.last_step_stored = 0;
  for (int i = 0; i < mesh_.n_nodes(); ++i)
    b.last_step_stored += matrices_.node_capacity[i] * (t1[node_dof_[i]] - t0[node_dof_[i]]);
  b.last_step_supplied = dt * source.sum();
  b.last_step_boundary = dt * boundary;
  b.stored += b.last_step_stored;
  b.supplied += b.last_step_supplied;
  b.boundary += b.last_step_boundary;

  s.closed = closed;
  s.previous_temperature = std::move(start);
  for (int i = 0; i < mesh_.n_nodes(); ++i) s.temperature[i] = t1[node_dof_[i]];
  s.previous_dt = dt;
  s.last_max_change = change;
  if (step_control_.enabled()) s.next_dt = step_control_.next_step(dt, change);
  publish(state);
  ++counters_.steps;
  counters_.smallest_step = counters_.steps == 1 ? dt : std::min(counters_.smallest_step, dt);
  counters_.largest_step = std::max(counters_.largest_step, dt);
  counters_.largest_change = std::max(counters_.largest_change, change);
  counters_.step_seconds += clock.seconds();
  return {};
}

std::vector<Vec2> ThermalProcess::node_positions(const RockMass& state) const {
  const std::vector<BlockMap> maps = block_maps(state.blocks, reference_);
  std::vector<Vec2> x(mesh_.nodes.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = maps[mesh_.node_block[i]](mesh_.nodes[i]);
  return x;
}

double ThermalProcess::temperature_at(const RockMass& state, int point) const {
  const ThermalState* s = state.fields.find(kThermalState);
  if (!s || point >= static_cast<int>(monitor_places_.size()) ||
      monitor_places_[point].triangle < 0)
    return std::numeric_limits<double>::quiet_NaN();
  const ThermalMesh::Place& place = monitor_places_[point];
  const auto& tri = mesh_.triangles[place.triangle];
  double value = 0;
  for (int k = 0; k < 3; ++k) value += place.weights[k] * s->temperature[tri[k]];
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
  j["system_builds"] = counters_.system_builds;
  j["factorizations"] = solver_.factorizations();
  j["solves"] = solver_.solves();
  j["factorization_seconds"] = solver_.factor_seconds();
  j["solve_seconds"] = solver_.solve_seconds();
  j["step_seconds"] = counters_.step_seconds;
  return j;
}

nlohmann::json ThermalProcess::energy(const RockMass& state) const {
  const ThermalState* s = state.fields.find(kThermalState);
  if (!s) return nlohmann::json::object();
  const EnergyBalance& b = s->balance;
  return {{"heat",
           {{"stored", b.stored},
            {"supplied_by_sources", b.supplied},
            {"through_boundaries", b.boundary},
            {"residual", b.residual()}}}};
}

template <class Archive>
void ThermalProcess::checkpoint(Archive& a, RockMass& state) {
  ThermalState& s = state.fields.get_or_add(kThermalState);
  a("temperature", s.temperature);
  a("previous_temperature", s.previous_temperature);
  a("previous_dt", s.previous_dt);
  a("closed", s.closed);
  a("next_dt", s.next_dt);
  a("last_max_change", s.last_max_change);
  EnergyBalance& b = s.balance;
  a("stored", b.stored);
  a("supplied", b.supplied);
  a("boundary", b.boundary);
  a("last_step_stored", b.last_step_stored);
  a("last_step_supplied", b.last_step_supplied);
  a("last_step_boundary", b.last_step_boundary);
  a("steps", counters_.steps);
  a("rejected_steps", counters_.rejected_steps);
  a("smallest_step", counters_.smallest_step);
  a("largest_step", counters_.largest_step);
  a("largest_change", counters_.largest_change);
  a("system_builds", counters_.system_builds);
  a("step_seconds", counters_.step_seconds);
  solver_.checkpoint_counters(a);
}

void ThermalProcess::save(CheckpointWriter& out, const RockMass& state) const {
  const_cast<ThermalProcess*>(this)->checkpoint(out, const_cast<RockMass&>(state));
}

void ThermalProcess::restore(CheckpointReader& in, RockMass& state) {
  checkpoint(in, state);
  const ThermalState& s = state.fields.get(kThermalState);
  FISSURE_CHECK(static_cast<int>(s.temperature.size()) == mesh_.n_nodes() &&
                    s.previous_temperature.size() == s.temperature.size() &&
                    s.closed.size() == mesh_.boundary_edges.size(),
                IoError,
                "the checkpoint's thermal mesh ("
                    << s.temperature.size() << " nodes) is not the scene's (" << mesh_.n_nodes()
                    << " nodes)");
  publish(state);
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
