#include "continuum/poroelasticity/continuum_process.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>

#include "continuum/poroelasticity/continuum_exchanged_fields.h"
#include "continuum/poroelasticity/continuum_linear_solver.h"
#include "continuum/poroelasticity/continuum_stress.h"
#include "continuum/poroelasticity/stress_permeability.h"
#include "continuum/poroelasticity/taylor_hood.h"
#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/parallel/mpi_world.h"
#include "core/process/exchanged_values.h"
#include "rockmass/fields/continuum_interface.h"

namespace fissure::continuum {

ContinuumProcess::ContinuumProcess(const Scene& scene)
    : c_(continuum_controls(scene)), gravity_(scene.gravity) {
  monitors_in_scene_ = scene.monitors;
  with_blocks_ = !scene.blocks.empty();
  for (const ContinuumCondition& k : c_.conditions)
    if (k.type == ContinuumCondition::Type::Interface) {
      reads_ = {std::string(kContinuumInterfaceLoads.name)};
      writes_ = {std::string(kContinuumInterfaces.name)};
    }
}

void ContinuumProcess::initialize(RockMass& state) {
  counters_ = {};
  Stopwatch clock;
  const double estimate = estimate_elements(c_);
  FISSURE_CHECK(estimate <= c_.max_elements, SceneError,
                fmt::format("{}: the mesh would have about {:.3g} triangles; expected at most "
                            "continuum.mesh.max_elements = {:.3g}: a larger element_size or "
                            "fewer divisions, or a larger max_elements",
                            c_.mesh_path, estimate, c_.max_elements));
  // The mesh, the Taylor-Hood systems and their factorization with the
  // direct solver: 26-28 kB a meshed triangle (143 MB at 4,418 triangles,
  // 1.43 GB at 51,245), 31.5 kB on a `divisions` mesh (2.52 GB at 80,000);
  // an iterative solver (`petsc`, or `auto` above kAutoIterativeUnknowns,
  // about 4.5 unknowns a triangle in the monolithic system) 16.9 kB (1.35
  // GB at 80,000; docs/performance.md "Memory"). Counted 32 and 17 kB a
  // meshed triangle. A `divisions` mesh has as many as estimated; a mesh
  // by element size 1.6 times fewer (the estimate is an upper one: 16.9 kB
  // an estimated triangle measured with the direct solver).
  const bool direct = c_.solver.type == LinearSolverControls::Type::Direct ||
                      (c_.solver.type == LinearSolverControls::Type::Auto &&
                       4.5 * estimate <= kAutoIterativeUnknowns);
  const double meshed = c_.divisions[0] > 0 ? estimate : estimate / 1.6;
  check_memory(meshed * (direct ? 32e3 : 17e3), c_.mesh_path,
               fmt::format("a mesh of about {:.3g} triangles with the {} solver", meshed,
                           direct ? "direct" : "iterative"));
  try {
    mesh_ = build_continuum_mesh(c_);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    throw SceneError(fmt::format("{}: cannot mesh the domain: {}", c_.mesh_path, e.what()));
  }
  for (const ContinuumCondition& k : c_.conditions)
    FISSURE_CHECK(!mesh_.boundary(k.boundary)->empty(), SceneError,
                  fmt::format("{}: boundary '{}' has no edge in the mesh; expected a side of the "
                              "domain's bounding box that the domain has, a hole, or a named "
                              "line along the outline",
                              k.path, k.boundary));
  counters_.mesh_seconds = clock.lap();
  // Each rank assembles its share of the triangles (all of them on one).
  owned_ = owned_triangles(mesh_, parallel::rank(), parallel::size());
  assemble_poroelastic(mesh_, c_, gravity_, owned_, matrices_);
  try {
    constraints_ = build_constraints(mesh_, c_.conditions, c_.axisymmetric, c_.linear_displacement);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    throw SceneError(fmt::format("{}: {}", c_.conditions_path, e.what()));
  }
  // Interfaces: their nodes, and the initial field as the value of what is
  // given until the other process gives it.
  interfaces_.clear();
  for (std::size_t k = 0; k < c_.conditions.size(); ++k) {
    if (c_.conditions[k].type != ContinuumCondition::Type::Interface) continue;
    Interface i;
    i.condition = static_cast<int>(k);
    i.vertices = constraints_.interface_vertices(c_.conditions[k].boundary);
    i.measure = constraints_.vertex_measure(c_.conditions[k].boundary, i.vertices);
    for (int v : i.vertices) {
      if (constraints_.pressure.condition[v] == i.condition)
        constraints_.pressure.value[v] = c_.initial_pressure_at(mesh_.nodes[v].y());
      if (constraints_.temperature.condition[v] == i.condition)
        constraints_.temperature.value[v] = c_.initial_temperature_at(mesh_.nodes[v].y());
    }
    interfaces_.push_back(std::move(i));
  }
  // A system that cannot be solved before the first step follows from the
  // scene (its solver, its mesh size, its conditions): located at the
  // solver the scene chose, else at the mesh, so that `validate` reports it
  // as a scene problem.
  try {
    solver_.emplace(mesh_, c_, matrices_, constraints_);
    solver_->compute_reactions(!interfaces_.empty());
    fields_ = solver_->initial_state();
    // The interfaces carry the in-situ stress until the other side gives
    // its tractions (a block region's first ones come after this start).
    Eigen::VectorXd held;
    for (const Interface& i : interfaces_) add_initial_traction(i, held);
    solver_->set_interface_load(std::move(held));
    if (c_.undrained_start) solver_->undrained_response(fields_, 0);
    // The tensors of the initial state (for its output; each step sets
    // them afresh from its own start).
    if (c_.stress_dependent_permeability())
      update_stress_permeability(mesh_, c_, fields_, matrices_);
    initial_permeability_ = matrices_.permeability;
  } catch (const SolverError& e) {
    throw unsolvable_at_start(c_.solver, c_.mesh_path, e);
  }
  previous_dt_ = 0;
  if (!interfaces_.empty()) {
    // Published afresh (replacing this continuum's earlier interfaces).
    auto& all = state.fields.get_or_add(kContinuumInterfaces);
    for (Interface& i : interfaces_) {
      const ContinuumCondition& k = c_.conditions[i.condition];
      std::erase_if(all, [&k](const ContinuumInterface& x) { return x.name == k.boundary; });
      all.push_back(published_interface(i));
    }
    give_interface_values(state);
  }
  counters_.assembly_seconds = clock.lap();
  monitor_places_.clear();
  for (std::size_t k = 0; k < monitors_in_scene_.size(); ++k) {
    const Monitor& m = monitors_in_scene_[k];
    ContinuumMesh::Place place = mesh_.locate(m.point);
    // A monitor outside the domain (or in a hole) would have no values:
    // refused in a continuum scene, as a block monitor outside every block
    // is; beside blocks it may watch them instead (no continuum values).
    if (place.weights.minCoeff() < -1e-9 && with_blocks_) place.triangle = -1;
    FISSURE_CHECK(place.triangle < 0 || place.weights.minCoeff() >= -1e-9, SceneError,
                  fmt::format("{}:{}:{}: monitors[{}].point: found [{:g}, {:g}], which is outside "
                              "the continuum's domain; expected a point in continuum.domain",
                              m.location.file, m.location.line, m.location.column, k, m.point.x(),
                              m.point.y()));
    monitor_places_.push_back(place);
  }
}

ContinuumInterface ContinuumProcess::published_interface(Interface& i) const {
  const ContinuumCondition& k = c_.conditions[i.condition];
  ContinuumInterface x;
  x.name = k.boundary;
  for (int v : i.vertices) x.nodes.push_back(mesh_.nodes[v]);
  std::vector<int> at(mesh_.n_vertices, -1);
  for (std::size_t a = 0; a < i.vertices.size(); ++a) at[i.vertices[a]] = static_cast<int>(a);
  i.edges = *mesh_.boundary(k.boundary);
  double perimeter = 0;
  for (const BoundaryEdge& e : i.edges) {
    x.edges.push_back({at[e.a], at[e.b]});
    perimeter += (mesh_.nodes[e.b] - mesh_.nodes[e.a]).norm();
  }
  x.takes = {k.gives.traction, k.gives.pressure, k.gives.fluid_flow, k.gives.temperature,
             k.gives.heat_flow};
  // The rock beside the interface: the mean of the triangles on its edges.
  std::set<std::pair<int, int>> on_interface;
  for (const BoundaryEdge& e : i.edges) on_interface.insert(std::minmax(e.a, e.b));
  double shear = 0, mobility = 0, conductivity = 0;
  int n = 0;
  for (int t = 0; t < mesh_.n_triangles(); ++t)
    for (int a = 0; a < 3; ++a) {
      const auto& tri = mesh_.triangles[t];
      if (!on_interface.count(std::minmax(tri[a], tri[(a + 1) % 3]))) continue;
      const PoroMaterial& m = c_.materials[mesh_.triangle_material[t]];
      const Eigen::Vector3d& kt = matrices_.permeability[t];
      shear += m.shear_modulus();
      mobility += (kt(0) + kt(1)) / 2 / c_.viscosity;
      conductivity += m.conductivity;
      ++n;
    }
  const double radius = perimeter / (2 * M_PI);
  if (n > 0 && radius > 0)
    x.impedance = {2 * shear / n / radius, mobility / n / radius, conductivity / n / radius};
  return x;
}

double ContinuumProcess::proposed_dt(const RockMass&) const {
  return c_.time_step > 0 ? c_.time_step : std::numeric_limits<double>::infinity();
}

StepReport ContinuumProcess::advance(RockMass& state, double t, double dt) {
  Stopwatch clock;
  take_interface_values(state);
  PoroState next;
  const StepStatistics stats = step_fields(next, t, dt);
  FISSURE_CHECK(
      next.displacement.allFinite() && next.pressure.allFinite() && next.temperature.allFinite(),
      DivergenceError,
      "the continuum's fields are not finite after the step from t = "
          << t << " s (dt = " << dt << " s); expected finite material parameters");
  previous_ = std::move(fields_);
  previous_dt_ = dt;
  fields_ = std::move(next);
  give_interface_values(state);
  ++counters_.steps;
  counters_.passes += stats.passes;
  counters_.most_passes = std::max(counters_.most_passes, stats.passes);
  counters_.largest_last_change = std::max(counters_.largest_last_change, stats.last_change);
  counters_.step_seconds += clock.seconds();
  return {};
}

StepStatistics ContinuumProcess::step_fields(PoroState& next, double t, double dt) {
  next = fields_;
  if (!c_.stress_dependent_permeability())
    return solver_->step(next, previous_, previous_dt_, t, dt);
  // The step starts from the tensors of its start's fields, computed from
  // them, never carried over, so that a restart is the same to the bit.
  update_stress_permeability(mesh_, c_, fields_, matrices_);
  assemble_flow_terms(mesh_, c_, gravity_, owned_, matrices_);
  solver_->flow_terms_changed();
  long passes = 0;
  const auto record = [&] {
    counters_.permeability_passes += passes;
    counters_.most_permeability_passes = std::max(counters_.most_permeability_passes, passes);
  };
  if (c_.scheme != ContinuumControls::Scheme::Monolithic) {
    // A staggered scheme updates the tensors after each of its passes, so
    // that the split and the tensors converge together (docs/continuum.md
    // section 9).
    solver_->set_flow_terms_update(
        [this, &passes](const PoroState& s) {
          ++passes;
          const double change = update_stress_permeability(mesh_, c_, s, matrices_);
          if (change > 0) assemble_flow_terms(mesh_, c_, gravity_, owned_, matrices_);
          return change;
        },
        kPermeabilityTolerance);
    // Cleared however the step ends (the update refers to this frame's `passes`).
    struct Clear {
      PoroelasticSolver& solver;
      ~Clear() { solver.set_flow_terms_update({}, 0); }
    } clear{*solver_};
    const StepStatistics stats = solver_->step(next, previous_, previous_dt_, t, dt);
    record();
    return stats;
  }
  // Monolithic: Picard passes of the whole step with the tensors of the last
  // pass's fields, until they settle.
  for (passes = 1;; ++passes) {
    next = fields_;
    const StepStatistics stats = solver_->step(next, previous_, previous_dt_, t, dt);
    const double change = update_stress_permeability(mesh_, c_, next, matrices_);
    if (change <= kPermeabilityTolerance) {
      record();
      return stats;
    }
    FISSURE_CHECK(passes < kMostPermeabilityPasses && std::isfinite(change), DivergenceError,
                  fmt::format("the stress-dependent permeability did not settle in the step from "
                              "t = {:g} s (dt = {:g} s): its tensors still changed by {:.3g} "
                              "(relative) after {} passes; expected a smaller continuum.time_step",
                              t, dt, change, passes));
    assemble_flow_terms(mesh_, c_, gravity_, owned_, matrices_);
    solver_->flow_terms_changed();
  }
}

template <class T>
const std::vector<InterfacePlace>& ContinuumProcess::place_points(
    Interface::Placed& cache, const ContinuumInterface& published, const ContinuumCondition& k,
    const InterfacePointLoads<T>& given, bool taken, const char* what, const char* key) {
  FISSURE_CHECK(taken, SolverError,
                fmt::format("{}: the interface '{}' was given {} at points; expected {} in its "
                            "interface list, or none given",
                            k.path, k.boundary, what, key));
  FISSURE_CHECK(given.points.size() == given.values.size(), SolverError,
                fmt::format("{}: the interface '{}' was given {} {} values at {} points; expected "
                            "one per point",
                            k.path, k.boundary, given.values.size(), what, given.points.size()));
  FISSURE_CHECK(!c_.axisymmetric, SolverError,
                fmt::format("{}: the interface '{}' was given {} at points; expected a plane "
                            "strain continuum (loads at points are per unit thickness)",
                            k.path, k.boundary, what));
  if (cache.points == given.points) return cache.places;
  const double tolerance = interface_tolerance(published);
  cache.places.clear();
  for (const Vec2& x : given.points) {
    const InterfacePlace place = locate_on_interface(published, x);
    FISSURE_CHECK(place.distance <= tolerance, SolverError,
                  fmt::format("{}: the interface '{}' was given {} at [{:.9g}, {:.9g}], {:.3g} m "
                              "from it; expected points on it (within {:.3g} m)",
                              k.path, k.boundary, what, x.x(), x.y(), place.distance, tolerance));
    cache.places.push_back(place);
  }
  cache.points = given.points;
  return cache.places;
}

namespace {

/// Pieces given on an interface: taken by its condition (`key` in its
/// list), each on one of its edges with 0 <= s0 <= s1 <= 1.
template <class T>
void check_pieces(const ContinuumCondition& k, std::size_t n_edges,
                  const std::vector<InterfacePiece<T>>& pieces, bool taken, const char* key) {
  FISSURE_CHECK(taken, SolverError,
                fmt::format("{}: the interface '{}' was given {} on pieces of its edges; "
                            "expected {} in its interface list, or none given",
                            k.path, k.boundary, key, key));
  for (const InterfacePiece<T>& p : pieces)
    FISSURE_CHECK(
        p.edge >= 0 && p.edge < static_cast<int>(n_edges) && p.s0 >= 0 && p.s1 <= 1 && p.s0 <= p.s1,
        SolverError,
        fmt::format("{}: the interface '{}' was given {} on edge {} from s = {:g} to "
                    "{:g}; expected an edge of its {} and 0 <= s0 <= s1 <= 1",
                    k.path, k.boundary, key, p.edge, p.s0, p.s1, n_edges));
}

}  // namespace

void ContinuumProcess::add_initial_traction(const Interface& i, Eigen::VectorXd& f) const {
  const ContinuumCondition& k = c_.conditions[i.condition];
  if (!k.gives.traction) return;
  if (c_.initial_stress.isZero() && c_.initial_stress_gradient.isZero()) return;
  const std::vector<BoundaryEdge>& edges = *mesh_.boundary(k.boundary);
  // sigma_0 is linear in y, so sigma_0 n is linear along each straight edge.
  auto traction = [&](const Vec2& x, const Vec2& n) {
    const Eigen::Vector3d s =
        c_.initial_stress + (x.y() - c_.reference_y) * c_.initial_stress_gradient;
    return Vec2(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
  };
  std::vector<TractionPiece> pieces;
  pieces.reserve(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Vec2 &a = mesh_.nodes[edges[e].a], &b = mesh_.nodes[edges[e].b];
    const Vec2 d = b - a;
    const Vec2 n = Vec2(d.y(), -d.x()).normalized();  // outward, as for normal_pressure
    pieces.push_back({static_cast<int>(e), 0, 1, traction(a, n), traction(b, n)});
  }
  if (f.size() == 0) f = Eigen::VectorXd::Zero(2 * mesh_.n_nodes());
  constraints_.add_interface_piece_traction(edges, pieces, f);
}

void ContinuumProcess::take_interface_values(RockMass& state) {
  if (interfaces_.empty()) return;
  std::vector<ContinuumInterfaceLoad>* all = state.fields.find(kContinuumInterfaceLoads);
  const std::vector<ContinuumInterface>* returned = state.fields.find(kContinuumInterfaces);
  FISSURE_CHECK(returned, std::logic_error, "the continuum's interfaces are not in the state");
  Eigen::VectorXd load, fluid, heat;
  for (Interface& i : interfaces_) {
    const ContinuumCondition& k = c_.conditions[i.condition];
    const ContinuumInterfaceLoad* x = all ? find_interface(*all, k.boundary) : nullptr;
    if (!x || (x->traction.empty() && x->traction_pieces.empty()))
      add_initial_traction(i, load);  // no traction given: the in-situ one
    if (!x) continue;                 // nothing else given
    const std::size_t n = i.vertices.size();
    // What the other process gives: one value per node, or nothing, and
    // only what the condition takes.
    auto check = [&](std::size_t size, bool taken, const char* what, const char* key) {
      FISSURE_CHECK(size == 0 || size == n, SolverError,
                    fmt::format("{}: the interface '{}' was given {} {} values; expected one per "
                                "node ({}) or none",
                                k.path, k.boundary, size, what, n));
      FISSURE_CHECK(size == 0 || taken, SolverError,
                    fmt::format("{}: the interface '{}' was given {} values; expected {} in its "
                                "interface list, or none given",
                                k.path, k.boundary, what, key));
    };
    check(x->traction.size(), k.gives.traction, "traction", "traction");
    check(x->pressure.size(), k.gives.pressure, "pressure", "pressure");
    check(x->temperature.size(), k.gives.temperature, "temperature", "temperature");
    if (!x->traction.empty()) {
      if (load.size() == 0) load = Eigen::VectorXd::Zero(2 * mesh_.n_nodes());
      constraints_.add_interface_traction(k.boundary, i.vertices, x->traction, load);
    }
    if (!x->traction_pieces.empty()) {
      check_pieces(k, i.edges.size(), x->traction_pieces, k.gives.traction, "traction");
      if (load.size() == 0) load = Eigen::VectorXd::Zero(2 * mesh_.n_nodes());
      constraints_.add_interface_piece_traction(i.edges, x->traction_pieces, load);
    }
    // A value not given holds the last one given (at first the initial field).
    for (std::size_t a = 0; a < n; ++a) {
      const int v = i.vertices[a];
      if (!x->pressure.empty() && constraints_.pressure.condition[v] == i.condition)
        constraints_.pressure.value[v] = x->pressure[a];
      if (!x->temperature.empty() && constraints_.temperature.condition[v] == i.condition)
        constraints_.temperature.value[v] = x->temperature[a];
    }
    // Inflows at points (continuum_interface.h): f_i += N_i(x) Q with the
    // linear shape functions of the edge the point lies on, the transposes
    // of the trace the other side reads.
    const ContinuumInterface& published = *find_interface(*returned, k.boundary);
    auto add_inflows = [&](Interface::Placed& cache, const InterfacePointLoads<double>& given,
                           bool taken, const char* what, const char* key, Eigen::VectorXd& f) {
      if (given.empty()) return;
      const auto& places = place_points(cache, published, k, given, taken, what, key);
      if (f.size() == 0) f = Eigen::VectorXd::Zero(mesh_.n_vertices);
      for (std::size_t q = 0; q < places.size(); ++q) {
        const BoundaryEdge& e = i.edges[places[q].edge];
        const std::array<double, 2> w = linear_weights(places[q].s);
        f(e.a) += w[0] * given.values[q];
        f(e.b) += w[1] * given.values[q];
      }
    };
    add_inflows(i.fluid, x->fluid, k.gives.fluid_flow, "fluid flow", "fluid_flow", fluid);
    if (!x->heat_flux_pieces.empty()) {
      check_pieces(k, i.edges.size(), x->heat_flux_pieces, k.gives.heat_flow, "heat_flow");
      if (heat.size() == 0) heat = Eigen::VectorXd::Zero(mesh_.n_vertices);
      constraints_.add_interface_piece_flux(i.edges, x->heat_flux_pieces, heat);
    }
  }
  solver_->set_interface_load(std::move(load));
  solver_->set_interface_inflows(std::move(fluid), std::move(heat));
}

void ContinuumProcess::give_interface_values(RockMass& state) const {
  if (interfaces_.empty()) return;
  std::vector<ContinuumInterface>& all = state.fields.get_or_add(kContinuumInterfaces);
  const Eigen::VectorXd &fluid = solver_->fluid_reaction(), &heat = solver_->heat_reaction();
  const bool with_heat = c_.with_temperature();
  for (const Interface& i : interfaces_) {
    ContinuumInterface* x = find_interface(all, c_.conditions[i.condition].boundary);
    if (!x) continue;
    const std::size_t n = i.vertices.size();
    x->displacement.assign(n, Vec2::Zero());
    x->fluid_flux.assign(n, 0);
    x->heat_flux.assign(n, 0);
    x->pressure.assign(n, 0);
    x->temperature.assign(with_heat ? n : 0, 0);
    for (std::size_t a = 0; a < n; ++a) {
      const int v = i.vertices[a];
      x->displacement[a] = fields_.displacement.segment<2>(2 * v);
      x->pressure[a] = fields_.pressure(v);
      if (with_heat) x->temperature[a] = fields_.temperature(v);
      // The reaction is the inflow the prescribed value supplies (m^3/s per
      // m, W/m); over the node's share of the boundary, the flux out.
      if (fluid.size() > 0 && constraints_.pressure.condition[v] >= 0)
        x->fluid_flux[a] = -fluid(v) / i.measure[a];
      if (heat.size() > 0 && with_heat && constraints_.temperature.condition[v] >= 0)
        x->heat_flux[a] = -heat(v) / i.measure[a];
    }
    x->midside_displacement.clear();
    for (const BoundaryEdge& e : i.edges)
      x->midside_displacement.push_back(fields_.displacement.segment<2>(2 * e.mid));
  }
}

template <class State, class Visit>
void ContinuumProcess::for_each_returned(State& state, Visit&& visit) const {
  auto* all = state.fields.find(kContinuumInterfaces);
  if (!all) return;
  for (const Interface& i : interfaces_)
    for (auto& x : *all) {
      if (x.name != c_.conditions[i.condition].boundary) continue;
      for (auto* us : {&x.displacement, &x.midside_displacement})
        for (auto& u : *us) {
          visit(kDisplacement, u.x());
          visit(kDisplacement, u.y());
        }
      for (auto& p : x.pressure) visit(kPressure, p);
      for (auto& temperature : x.temperature) visit(kTemperature, temperature);
      for (auto& q : x.fluid_flux) visit(kFluidFlux, q);
      for (auto& q : x.heat_flux) visit(kHeatFlux, q);
    }
}

std::vector<ExchangedField> ContinuumProcess::exchanged_values(const RockMass& state) const {
  return gather_exchanged(state, kExchangedFields,
                          [this](const RockMass& s, auto&& visit) { for_each_returned(s, visit); });
}

void ContinuumProcess::set_exchanged_values(RockMass& state,
                                            std::span<const ExchangedField> values) {
  scatter_exchanged(state, values,
                    [this](RockMass& s, auto&& visit) { for_each_returned(s, visit); });
}

PointValues ContinuumProcess::values_in(int t, const Eigen::Vector3d& w) const {
  const std::array<int, 6>& tri = mesh_.triangles[t];
  const TriangleGeometry g({mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]]},
                           c_.axisymmetric, c_.linear_displacement);
  const Eigen::Matrix<double, 6, 1> n = displacement_values(g, w);
  PointValues v;
  for (int a = 0; a < 6; ++a) v.displacement += n(a) * fields_.displacement.segment<2>(2 * tri[a]);
  const Eigen::Vector3d p(fields_.pressure(tri[0]), fields_.pressure(tri[1]),
                          fields_.pressure(tri[2]));
  v.pressure = w.dot(p);
  v.temperature = w.dot(Eigen::Vector3d(fields_.temperature(tri[0]), fields_.temperature(tri[1]),
                                        fields_.temperature(tri[2])));
  v.stress = total_stress(mesh_, c_, matrices_, fields_, t, w);
  // q = -(k / mu) (grad p - rho_f g), with the triangle's present k.
  const Eigen::Vector3d& kt = matrices_.permeability[t];
  Eigen::Matrix2d k;
  k << kt(0), kt(2), kt(2), kt(1);
  v.darcy_flux = -(k / c_.viscosity) * (p1_gradients(g) * p - c_.fluid_density * gravity_);
  return v;
}

nlohmann::json ContinuumProcess::statistics() const {
  nlohmann::json j = {
      {"mesh",
       {{"triangles", mesh_.n_triangles()},
        {"displacement_nodes", mesh_.n_nodes()},
        {"vertices", mesh_.n_vertices},
        {"unknowns", constraints_.displacement.n_free + constraints_.pressure.n_free +
                         (c_.with_temperature() ? constraints_.temperature.n_free : 0)}}},
      {"geometry", c_.axisymmetric ? "axisymmetric" : "plane_strain"},
      {"scheme", ContinuumControls::scheme_name(c_.scheme)},
      {"coupling_strength", largest_coupling_strength(mesh_, c_)},
      {"steps", counters_.steps},
      {"splitting_passes", counters_.passes},
      {"most_passes_in_a_step", counters_.most_passes},
      {"largest_final_change", counters_.largest_last_change},
      {"factorizations", solver_ ? solver_->factorizations() : 0},
      {"linear_solves", solver_ ? solver_->linear_solves() : 0},
      {"linear_iterations", solver_ ? solver_->linear_iterations() : 0},
      {"linear_solver", solver_ ? solver_->linear_solver() : "none"},
      {"factors", solver_ ? solver_->factor_sizes() : nlohmann::json::object()},
      {"ranks", parallel::size()},
      {"seconds",
       {{"mesh", counters_.mesh_seconds},
        {"assembly", counters_.assembly_seconds},
        {"steps", counters_.step_seconds}}}};
  if (c_.stress_dependent_permeability())
    j["stress_dependent_permeability"] = {
        {"passes", counters_.permeability_passes},
        {"most_passes_in_a_step", counters_.most_permeability_passes},
        {"tolerance", kPermeabilityTolerance}};
  return j;
}

template <class Self, class Archive>
void ContinuumProcess::checkpoint(Self& self, Archive& a) {
  a("displacement", self.fields_.displacement);
  a("pressure", self.fields_.pressure);
  a("temperature", self.fields_.temperature);
  a("previous_displacement", self.previous_.displacement);
  a("previous_pressure", self.previous_.pressure);
  a("previous_temperature", self.previous_.temperature);
  a("previous_dt", self.previous_dt_);
  PoroelasticSolver::checkpoint_scales(*self.solver_, a);
  PoroelasticSolver::checkpoint_counters(*self.solver_, a);
  a("steps", self.counters_.steps);
  a("passes", self.counters_.passes);
  a("most_passes", self.counters_.most_passes);
  a("largest_last_change", self.counters_.largest_last_change);
  a("step_seconds", self.counters_.step_seconds);
  if (self.c_.stress_dependent_permeability()) {
    a("permeability_passes", self.counters_.permeability_passes);
    a("most_permeability_passes", self.counters_.most_permeability_passes);
  }
}

void ContinuumProcess::save(CheckpointWriter& out, const RockMass& state) const {
  checkpoint(*this, out);
  if (interfaces_.empty()) return;
  // The values last given (prescribed) and the returned shared field.
  out("interface_pressures", constraints_.pressure.value);
  out("interface_temperatures", constraints_.temperature.value);
  std::vector<double> returned;
  for_each_returned(state, [&](std::size_t, double v) { returned.push_back(v); });
  out("interface_returned", returned);
}

void ContinuumProcess::restore(CheckpointReader& in, RockMass& state) {
  checkpoint(*this, in);
  if (!interfaces_.empty()) {
    in("interface_pressures", constraints_.pressure.value);
    in("interface_temperatures", constraints_.temperature.value);
    std::vector<double> returned;
    in("interface_returned", returned);
    std::size_t n = 0;
    for_each_returned(state, [&](std::size_t, double) { ++n; });
    if (n == returned.size()) {
      std::size_t k = 0;
      for_each_returned(state, [&](std::size_t, double& v) { v = returned[k++]; });
    }
  }
  FISSURE_CHECK(fields_.displacement.size() == 2 * mesh_.n_nodes() &&
                    fields_.pressure.size() == mesh_.n_vertices &&
                    fields_.temperature.size() == mesh_.n_vertices,
                IoError,
                "the checkpoint's continuum mesh (" << fields_.pressure.size()
                                                    << " vertices) is not the scene's ("
                                                    << mesh_.n_vertices << " vertices)");
  // The tensors of the restored fields (as the uninterrupted run has them).
  if (c_.stress_dependent_permeability()) update_stress_permeability(mesh_, c_, fields_, matrices_);
}

}  // namespace fissure::continuum
