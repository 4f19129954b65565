#include "continuum/poroelasticity/continuum_process.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "continuum/poroelasticity/taylor_hood.h"
#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/parallel/mpi_world.h"

namespace fissure::continuum {

ContinuumProcess::ContinuumProcess(const Scene& scene)
    : c_(continuum_controls(scene)), gravity_(scene.gravity) {
  monitors_in_scene_ = scene.monitors;
  with_blocks_ = !scene.blocks.empty();
}

void ContinuumProcess::initialize(RockMass&) {
  counters_ = {};
  Stopwatch clock;
  const double estimate = estimate_elements(c_);
  FISSURE_CHECK(estimate <= c_.max_elements, SceneError,
                fmt::format("{}: the mesh would have about {:.3g} triangles; expected at most "
                            "continuum.mesh.max_elements = {:.3g}: a larger element_size or "
                            "fewer divisions, or a larger max_elements",
                            c_.mesh_path, estimate, c_.max_elements));
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
  matrices_ = assemble_poroelastic(mesh_, c_, gravity_,
                                   owned_triangles(mesh_, parallel::rank(), parallel::size()));
  try {
    constraints_ = build_constraints(mesh_, c_.conditions, c_.axisymmetric, c_.linear_displacement);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    throw SceneError(fmt::format("{}: {}", c_.conditions_path, e.what()));
  }
  solver_.emplace(mesh_, c_, matrices_, constraints_);
  fields_ = solver_->initial_state();
  previous_dt_ = 0;
  if (c_.undrained_start) solver_->undrained_response(fields_, 0);
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

double ContinuumProcess::proposed_dt(const RockMass&) const {
  return c_.time_step > 0 ? c_.time_step : std::numeric_limits<double>::infinity();
}

StepReport ContinuumProcess::advance(RockMass&, double t, double dt) {
  Stopwatch clock;
  PoroState next = fields_;
  const StepStatistics stats = solver_->step(next, previous_, previous_dt_, t, dt);
  FISSURE_CHECK(
      next.displacement.allFinite() && next.pressure.allFinite() && next.temperature.allFinite(),
      DivergenceError,
      "the continuum's fields are not finite after the step from t = "
          << t << " s (dt = " << dt << " s); expected finite material parameters");
  previous_ = std::move(fields_);
  previous_dt_ = dt;
  fields_ = std::move(next);
  ++counters_.steps;
  counters_.passes += stats.passes;
  counters_.most_passes = std::max(counters_.most_passes, stats.passes);
  counters_.largest_last_change = std::max(counters_.largest_last_change, stats.last_change);
  counters_.step_seconds += clock.seconds();
  return {};
}

PointValues ContinuumProcess::values_in(int t, const Eigen::Vector3d& w) const {
  const std::array<int, 6>& tri = mesh_.triangles[t];
  const TriangleGeometry g({mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]]},
                           c_.axisymmetric, c_.linear_displacement);
  Vector12 u;
  for (int a = 0; a < 6; ++a) u.segment<2>(2 * a) = fields_.displacement.segment<2>(2 * tri[a]);
  const Eigen::Matrix<double, 6, 1> n = displacement_values(g, w);
  PointValues v;
  for (int a = 0; a < 6; ++a) v.displacement += n(a) * u.segment<2>(2 * a);
  const Eigen::Vector3d p(fields_.pressure(tri[0]), fields_.pressure(tri[1]),
                          fields_.pressure(tri[2]));
  const Eigen::Vector3d temp(fields_.temperature(tri[0]), fields_.temperature(tri[1]),
                             fields_.temperature(tri[2]));
  v.pressure = w.dot(p);
  v.temperature = w.dot(temp);
  const Vec2 x = w(0) * g.x[0] + w(1) * g.x[1] + w(2) * g.x[2];
  const double p0 = c_.initial_pressure_at(x.y()), t0 = c_.initial_temperature_at(x.y());
  // sigma = sigma_0 + D eps - (alpha (p - p_0) + 3 K alpha_T (T - T_0)) I
  // (the out-of-plane or hoop stress too).
  const Vector4 m(1, 1, 0, 1);
  v.stress = initial_stress4(c_.initial_stress) +
             (x.y() - c_.reference_y) * initial_stress4(c_.initial_stress_gradient) +
             matrices_.elasticity[t] * (strain_matrix(g, w) * u) -
             (matrices_.biot[t] * (v.pressure - p0) +
              matrices_.thermal_stress_modulus[t] * (v.temperature - t0)) *
                 m;
  // q = -(k / mu) (grad p - rho_f g).
  const PoroMaterial& mat = c_.materials[mesh_.triangle_material[t]];
  Eigen::Matrix2d k;
  k << mat.permeability(0), mat.permeability(2), mat.permeability(2), mat.permeability(1);
  v.darcy_flux = -(k / c_.viscosity) * (p1_gradients(g) * p - c_.fluid_density * gravity_);
  return v;
}

nlohmann::json ContinuumProcess::statistics() const {
  const char* schemes[] = {"fixed_stress", "monolithic", "drained", "undrained"};
  return {{"mesh",
           {{"triangles", mesh_.n_triangles()},
            {"displacement_nodes", mesh_.n_nodes()},
            {"vertices", mesh_.n_vertices},
            {"unknowns", constraints_.displacement.n_free + constraints_.pressure.n_free +
                             (c_.with_temperature() ? constraints_.temperature.n_free : 0)}}},
          {"scheme", schemes[static_cast<int>(c_.scheme)]},
          {"coupling_strength", largest_coupling_strength(mesh_, c_)},
          {"steps", counters_.steps},
          {"splitting_passes", counters_.passes},
          {"most_passes_in_a_step", counters_.most_passes},
          {"largest_final_change", counters_.largest_last_change},
          {"factorizations", solver_ ? solver_->factorizations() : 0},
          {"linear_solves", solver_ ? solver_->linear_solves() : 0},
          {"linear_iterations", solver_ ? solver_->linear_iterations() : 0},
          {"linear_solver", solver_ ? solver_->linear_solver() : "none"},
          {"ranks", parallel::size()},
          {"seconds",
           {{"mesh", counters_.mesh_seconds},
            {"assembly", counters_.assembly_seconds},
            {"steps", counters_.step_seconds}}}};
}

template <class Archive>
void ContinuumProcess::checkpoint(Archive& a) {
  a("displacement", fields_.displacement);
  a("pressure", fields_.pressure);
  a("temperature", fields_.temperature);
  a("previous_displacement", previous_.displacement);
  a("previous_pressure", previous_.pressure);
  a("previous_temperature", previous_.temperature);
  a("previous_dt", previous_dt_);
  solver_->checkpoint_scales(a);
  a("steps", counters_.steps);
  a("passes", counters_.passes);
  a("most_passes", counters_.most_passes);
  a("largest_last_change", counters_.largest_last_change);
  a("step_seconds", counters_.step_seconds);
}

void ContinuumProcess::save(CheckpointWriter& out, const RockMass&) const {
  const_cast<ContinuumProcess*>(this)->checkpoint(out);
}

void ContinuumProcess::restore(CheckpointReader& in, RockMass&) {
  checkpoint(in);
  FISSURE_CHECK(fields_.displacement.size() == 2 * mesh_.n_nodes() &&
                    fields_.pressure.size() == mesh_.n_vertices &&
                    fields_.temperature.size() == mesh_.n_vertices,
                IoError,
                "the checkpoint's continuum mesh (" << fields_.pressure.size()
                                                    << " vertices) is not the scene's ("
                                                    << mesh_.n_vertices << " vertices)");
}

}  // namespace fissure::continuum
