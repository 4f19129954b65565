#include "thermal/conduction/thermal_process.h"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <tuple>

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/stopwatch.h"
#include "core/geometry/union_find.h"
#include "core/process/exchanged_values.h"
#include "core/scene/scene_section.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/continuum_interface.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/rock_mass_spec.h"
#include "thermal/conduction/thermal_exchanged_fields.h"

namespace fissure::thermal {

namespace {

/// The finest element at the sources, relative to the global size.
constexpr double kFinestRelativeSize = 1e-4;

}  // namespace

ThermalProcess::ThermalProcess(const Scene& scene)
    : c_(thermal_controls(scene)),
      step_control_{c_.max_temperature_change, c_.time_step},
      with_mechanics_(provides(scene, kContacts.name)) {
  // Scenes built in code may leave materials out: the defaults then.
  if (c_.materials.size() < scene.materials.size()) c_.materials.resize(scene.materials.size());
  if (const RockMassSpec* spec = scene.sections.find(kRockMassSpec))
    for (const ExcavationSpec& e : spec->excavations) walls_.push_back({e.name, e.vertices});
  if (c_.convection) {
    FISSURE_CHECK(provides(scene, kFractureFlow.name), SceneError,
                  c_.convection->path << ": found thermal.convection without the flow process; "
                                         "expected `flow` in physics (the fracture water's flux "
                                         "comes from the flow)");
    fluid_.emplace(*c_.convection, c_.lumped_capacity);
  }
}

std::vector<std::string> ThermalProcess::reads() const {
  std::vector<std::string> fields = {std::string(block_fields::geometry)};
  if (with_mechanics_) fields.emplace_back(kContacts.name);
  if (!ties_.empty()) fields.emplace_back(kContinuumInterfaces.name);
  if (fluid_) {
    fields.emplace_back(kFractureGraph.name);
    fields.emplace_back(kFractureFlow.name);
  }
  return fields;
}

std::vector<std::string> ThermalProcess::writes() const {
  std::vector<std::string> fields = kThermalSection.provided_fields();
  if (fluid_) fields.emplace_back(kFractureFluidTemperature.name);
  if (!ties_.empty()) fields.emplace_back(kContinuumInterfaceLoads.name);
  return fields;
}

double ThermalProcess::proposed_dt(const RockMass&) const {
  if (!(c_.time_step > 0)) return std::numeric_limits<double>::infinity();
  if (step_control_.enabled() && s_.next_dt > 0) return s_.next_dt;
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
    // Two fixed blocks never move apart, and the mechanics looks for no
    // contact between them: their faces stay as cut, closed.
    if (state.blocks[a.block].fixed && state.blocks[b.block].fixed) {
      closed[e] = 1;
      continue;
    }
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
  // Each set's root its smallest node: the unknowns numbered in node order.
  UnionFind merged(n);
  std::vector<EdgeTransfer> joints, convective;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!closed[e]) continue;
    const BoundaryEdge &a = edges[e], &b = edges[a.partner];
    if (c_.perfect_contact) {
      for (const auto& [x, y] : {std::pair{a.a, b.b}, std::pair{a.b, b.a}})
        merged.unite_to_smallest(x, y);
    } else if (c_.contact_conductance > 0) {
      joints.push_back({static_cast<int>(e), c_.contact_conductance});
    }
  }
  // The water at its walls' temperature (h -> infinity): the walls at a
  // fluid node are one unknown, with the water.
  if (fluid_ && fluid_->built())
    for (const std::vector<int>& walls : fluid_->merged_walls())
      for (std::size_t k = 1; k < walls.size(); ++k) merged.unite_to_smallest(walls[0], walls[k]);
  node_dof_.assign(n, -1);
  std::vector<int> root_dof(n, -1);
  n_dofs_ = 0;
  for (int i = 0; i < n; ++i) {
    const int r = merged.find(i);
    if (root_dof[r] < 0) root_dof[r] = n_dofs_++;
    node_dof_[i] = root_dof[r];
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k >= 0 && c_.conditions[k].type == ThermalCondition::Type::Convection)
      convective.push_back({static_cast<int>(e), c_.conditions[k].value});
  }
  ties_.add_transfers(convective);
  matrices_ = conduction_matrices(mesh_, props_, node_dof_, n_dofs_, c_.lumped_capacity, joints,
                                  convective);
  system_has_fluid_ = fluid_ && fluid_->built();
  n_unknowns_ = system_has_fluid_ ? fluid_->number(node_dof_, n_dofs_) : n_dofs_;
  fixed_dof_.assign(n_unknowns_, false);
  fixed_condition_.assign(n_unknowns_, -1);
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
  restored_coefficient_ = -1;  // a new system: no factor of the checkpoint's stands for it
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
  // The meshes are made on the blocks as they were cut (initial_vertices),
  // where two blocks' faces coincide exactly and pair up as joints; blocks
  // that have settled (coupling.initial_equilibrium) have moved apart by
  // round-off-sized amounts that would leave every face unpaired, and no
  // heat would cross any joint. The meshes follow the blocks from there.
  std::vector<Block> as_cut = state.blocks;
  // Everything below is of the blocks as cut, so that a restart, which
  // starts from the scene, makes the same meshes and estimates.
  for (Block& b : as_cut)
    if (b.initial_vertices.size() == b.polygon.vertices.size()) {
      b.polygon.vertices = b.initial_vertices;
      b.section = section_properties(b.polygon);
    }
  reference_.assign(state.blocks.size(), {});
  Box all;
  double area = 0;
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    reference_[b] = as_cut[b].polygon.vertices;
    all.extend(bounding_box(as_cut[b].polygon));
    area += std::abs(as_cut[b].section.area);
  }
  const SizeField size(c_, all.size().maxCoeff());
  // Refinement towards a point stops being representable well before
  // 1e-12 of the model (CGAL's circumcentres collapse): a floor far above.
  FISSURE_CHECK(
      size.at_sources() >= kFinestRelativeSize * size.global(), SceneError,
      fmt::format("{}: found elements of {:g} m at the sources and {:g} m elsewhere; "
                  "expected source_element_size at least element_size / {:g}",
                  c_.mesh_path, size.at_sources(), size.global(), 1 / kFinestRelativeSize));
  source_block_ = source_blocks(c_.sources, as_cut);
  counters_.estimated_elements = size.estimate_elements(as_cut);
  FISSURE_CHECK(counters_.estimated_elements <= c_.max_elements, SceneError,
                fmt::format("{}: the block meshes would have about {:.3g} triangles (element "
                            "size {:g} m, {:g} m at the sources, over {:.4g} m^2 of rock); "
                            "expected at most thermal.mesh.max_elements = {:.3g}: a larger "
                            "element_size, or a larger max_elements",
                            c_.mesh_path, counters_.estimated_elements, size.global(),
                            size.at_sources(), area, c_.max_elements));
  // The meshes and the conduction system: at least 0.5 kB a triangle
  // (0.7 kB measured between 48,165 and 196,630 triangles).
  check_memory(counters_.estimated_elements * 500, c_.mesh_path,
               fmt::format("block meshes of about {:.3g} triangles", counters_.estimated_elements));
  try {
    mesh_ = build_thermal_mesh(as_cut, size, c_.sources, source_block_, walls_);
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
  ties_ = ThermalTies::find(mesh_, state);

  // The initial field: uniform or a gradient (the boundary temperatures
  // apply from the first step on).
  s_ = {};
  ThermalState& s = s_;
  s.temperature.resize(mesh_.n_nodes());
  for (int i = 0; i < mesh_.n_nodes(); ++i)
    s.temperature[i] = c_.initial_temperature_at(mesh_.nodes[i]);
  s.closed = closed_faces(state);
  if (fluid_) {
    fluid_.emplace(*c_.convection, c_.lumped_capacity);
    if (state.fields.find(kFractureGraph) && state.fields.find(kFractureFlow)) build_fluid(state);
  }
  build_system(s.closed);
  equalize(s.temperature);
  s.previous_temperature = s.temperature;
  s.previous_fluid_temperature = s.fluid_temperature;

  // Each block's stress-free temperature: its mean initial temperature.
  // A node belongs to one block (its own mesh), so a block's mean of P1
  // values is a sum over its nodes with weights A_t / 3 of their
  // triangles: one pass over the nodes each step instead of a gather over
  // the triangles.
  block_area_.assign(state.blocks.size(), 0.0);
  node_mean_weight_.assign(mesh_.n_nodes(), 0.0);
  for (int t = 0; t < mesh_.n_triangles(); ++t) {
    block_area_[mesh_.triangle_block[t]] += mesh_.triangle_area[t];
    for (const int node : mesh_.triangles[t]) node_mean_weight_[node] += mesh_.triangle_area[t] / 3;
  }
  block_reference_temperature_ = block_means(s.temperature);
  publish(state);
  if (!ties_.empty()) ties_.give_none(state);

  // Monitors: the triangle of their block that holds them, and the weights
  // (a monitor fixed in space: the triangle of any block that holds it at
  // the start, if one does; 1e-9: on a triangle's edge). A point in a block
  // is placed where it was as cut, as the mesh is: after an initial stage it
  // has moved with its block, and a restart (which initializes on the scene
  // as cut) would place it elsewhere in its triangle.
  monitor_places_.assign(state.points.size(), {});
  for (std::size_t p = 0; p < state.points.size(); ++p) {
    const MaterialPoint& point = state.points[p];
    monitor_places_[p] =
        mesh_.locate(point.block >= 0 ? point.initial : point.current, point.block);
    if (point.block < 0 && !(monitor_places_[p].weights.minCoeff() >= -1e-9))
      monitor_places_[p] = {};
  }
  counters_.mesh_seconds = clock.seconds();
}

std::vector<double> ThermalProcess::block_means(const std::vector<double>& t) const {
  std::vector<double> mean(block_area_.size(), 0.0);
  for (int n = 0; n < mesh_.n_nodes(); ++n)
    mean[mesh_.node_block[n]] += node_mean_weight_[n] * t[n];
  for (std::size_t b = 0; b < mean.size(); ++b) mean[b] /= block_area_[b];
  return mean;
}

void ThermalProcess::publish(RockMass& state) {
  ThermalState& s = s_;
  s.block_temperature_change = block_means(s.temperature);
  std::vector<double> strain(s.block_temperature_change.size());
  for (std::size_t b = 0; b < strain.size(); ++b) {
    s.block_temperature_change[b] -= block_reference_temperature_[b];
    strain[b] =
        c_.materials[state.blocks[b].material].thermal_expansion * s.block_temperature_change[b];
  }
  state.fields.set(kBlockThermalStrain, std::move(strain));
  if (fluid_ && fluid_->built() &&
      static_cast<int>(s.fluid_temperature.size()) == fluid_->n_nodes())
    state.fields.set(kFractureFluidTemperature,
                     fluid_->segment_means(state.fields.get(kFractureGraph), s.fluid_temperature));
}

void ThermalProcess::set_temperature(RockMass& state, std::vector<double> temperature) {
  FISSURE_CHECK(static_cast<int>(temperature.size()) == mesh_.n_nodes(), std::invalid_argument,
                "thermal: " << temperature.size() << " temperatures for " << mesh_.n_nodes()
                            << " mesh nodes");
  s_.temperature = std::move(temperature);
  s_.previous_temperature = s_.temperature;
  publish(state);
}

namespace {

/// Visits the exchanged values (thermal_exchanged_fields.h) in one order.
template <class Visit>
void for_each_exchanged(auto& state, Visit&& visit) {
  if (auto* strains = state.fields.find(kBlockThermalStrain))
    for (auto& v : *strains) visit(kStrain, v);
  if (auto* temperatures = state.fields.find(kFractureFluidTemperature))
    for (auto& v : *temperatures) visit(kFluidTemperature, v);
}

}  // namespace

std::vector<ExchangedField> ThermalProcess::exchanged_values(const RockMass& state) const {
  std::vector<ExchangedField> fields = gather_exchanged(
      state, kExchangedFields, [](auto& s, auto&& visit) { for_each_exchanged(s, visit); });
  if (!ties_.empty()) fields[kTieHeatFlow].values = ties_.mortar().given_resultants(state);
  return fields;
}

void ThermalProcess::set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) {
  scatter_exchanged(state, values, [](auto& s, auto&& visit) { for_each_exchanged(s, visit); });
  // The heat flows given at the ties: set when their layout is the ties'.
  if (!ties_.empty() && values.size() > kTieHeatFlow &&
      values[kTieHeatFlow].values.size() == ties_.mortar().n_values())
    ties_.mortar().set_given_resultants(state, values[kTieHeatFlow].values);
}

bool ThermalProcess::build_fluid(RockMass& state) {
  if (fluid_->built()) return false;
  const FractureGraph* graph = state.fields.find(kFractureGraph);
  FISSURE_CHECK(graph && state.fields.find(kFractureFlow), SolverError,
                c_.convection->path << ": no fracture network with flow to carry the heat (the "
                                       "flow process has not built its network)");
  Box all;
  for (const Vec2& x : mesh_.nodes) all.extend(x);
  const double tolerance = 1e-9 * std::max(1.0, all.empty() ? 1.0 : all.size().maxCoeff());
  fluid_->build(*graph, mesh_, tolerance,
                [this](const Vec2& x) { return c_.initial_temperature_at(x); });
  start_fluid();
  return true;
}

void ThermalProcess::start_fluid() {
  ThermalState& s = s_;
  // Temperatures already there (a restored checkpoint) are kept; otherwise
  // the water starts at the rock's initial temperature where it is.
  if (static_cast<int>(s.fluid_temperature.size()) == fluid_->n_nodes()) return;
  s.fluid_temperature.resize(fluid_->n_nodes());
  for (int i = 0; i < fluid_->n_nodes(); ++i) {
    const Vec2& x = fluid_->grid().positions[i];
    s.fluid_temperature[i] = c_.initial_temperature_at(x);
  }
  s.previous_fluid_temperature = s.fluid_temperature;
}

SparseMatrix ThermalProcess::step_matrix(double coefficient) const {
  SparseMatrix rock(coefficient * matrices_.capacity + matrices_.conductance);
  if (!fluid_) return rock;
  std::vector<FractureFluid::Triplet> entries;
  entries.reserve(rock.nonZeros() + 20 * fluid_->grid().pieces.size());
  for (int col = 0; col < rock.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(rock, col); it; ++it)
      entries.emplace_back(it.row(), it.col(), it.value());
  fluid_->add_matrix(coefficient, node_dof_, entries);
  SparseMatrix a(n_unknowns_, n_unknowns_);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

}  // namespace fissure::thermal
