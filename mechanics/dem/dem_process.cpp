#include "mechanics/dem/dem_process.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/scene/time_history.h"
#include "mechanics/dem/contact_kinematics.h"
#include "mechanics/dem/zone_mesh.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/pressure_loads.h"
#include "rockmass/joints/joint_model.h"

namespace fissure::dem {

namespace {

// A contact whose walls overlap by more than the rounding length has a
// corner deeper in the other block than its arc: the cycle's step was too
// long for the blocks' speed. The update is retried with half the step.
constexpr double kStepCut = 0.5;
// After a good update the step grows back towards the safety factor's.
constexpr double kStepGrowth = 1.3;

/// The direction of a block's first edge (rad): its turn over an update.
double edge_angle(const Polygon& p) {
  const Vec2 e = p.vertices[1] - p.vertices[0];
  return std::atan2(e.y(), e.x());
}

}  // namespace

DemProcess::DemProcess(const Scene& scene)
    : c_(section_settings(scene, kDemSettings)), point_loads_(scene.point_loads) {}

std::vector<std::string> DemProcess::reads() const {
  return {std::string(block_fields::geometry), std::string(block_fields::kinematics),
          std::string(kContacts.name), std::string(kPressureLoads.name),
          std::string(kBlockThermalStrain.name)};
}

std::vector<std::string> DemProcess::writes() const {
  std::vector<std::string> fields = kDemSection.provided_fields();
  if (!ties_.empty()) fields.emplace_back(kContinuumInterfaceLoads.name);
  return fields;
}

void DemProcess::build_system(const RockMass& state) {
  std::vector<joints::JointLaw> laws;
  for (const JointProperties& j : state.joints) laws.emplace_back(joints::joint_model(j));
  std::vector<DemBlock> blocks;
  blocks.reserve(state.blocks.size());
  for (const Block& b : state.blocks) {
    DemBlock d;
    d.polygon = b.polygon;
    d.centroid = b.section.centroid;
    d.body = rigid_body(b.section, state.materials[b.material].density);
    d.velocity = b.fixed ? Motion::Zero() : Motion(b.velocity.head<3>());
    d.fixed = b.fixed;
    d.edge_joint = b.edge_joint;
    d.initial_stress = b.stress;  // before the first step: the scene's initial stress
    if (c_.zone_size && !b.fixed) {
      const Material& m = state.materials[b.material];
      ZonedBlock z(mesh_block(b.polygon, *c_.zone_size),
                   {m.young_modulus, m.poisson_ratio, m.density});
      // The initial stress in the zones too (plane strain: s_zz = nu (s_xx + s_yy)).
      z.set_stress(
          {b.stress(0), b.stress(1), b.stress(2), m.poisson_ratio * (b.stress(0) + b.stress(1))});
      d.zoned = std::move(z);
    }
    blocks.push_back(std::move(d));
  }
  DemSettings s;
  s.rounding = rounding_;
  s.margin = margin_;
  s.gravity = state.gravity;
  s.damping.local = c_.local_damping;
  s.damping.mass = c_.mass_damping;
  s.stiffness_damping = c_.stiffness_damping;
  system_ = std::make_unique<DemSystem>(std::move(blocks), std::move(laws), s);
}

void DemProcess::initialize(RockMass& state) {
  first_load_point_ = state.first_load_point;
  // The rounding and the margin (docs/dem.md section 2).
  std::vector<double> edges;
  for (const Block& b : state.blocks)
    for (int v = 0; v < b.polygon.n_vertices(); ++v)
      edges.push_back((b.polygon.vertices[b.polygon.next(v)] - b.polygon.vertices[v]).norm());
  FISSURE_CHECK(!edges.empty(), SceneError, "the DEM needs blocks");
  const double shortest = *std::min_element(edges.begin(), edges.end());
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  // The default: 1 % of the median edge, but below half the shortest (a
  // sliver's corners would otherwise reach through it).
  rounding_ = c_.rounding.value_or(std::min(0.01 * edges[edges.size() / 2], 0.5 * shortest));
  margin_ = c_.margin.value_or(rounding_);
  thermal_strain_.assign(state.blocks.size(), 0.0);
  step_scale_ = 1;
  build_system(state);
  locate_points(state);
  system_->prepare();
  if (c_.time_step) {
    const double critical = system_->critical_time_step();
    const SourceLocation& at = c_.time_step_location;
    FISSURE_CHECK(*c_.time_step <= critical, SceneError,
                  fmt::format("{}:{}:{}: dem.time_step: found {:.4g} s, above the critical step "
                              "{:.4g} s of the blocks on their joints' stiffness (2 sqrt(m/k), "
                              "docs/dem.md section 2); expected at most {:.4g} s, or `auto`",
                              at.file, at.line, at.column, *c_.time_step, critical, critical));
  }
  publish_contacts(state);
  // Blocks tied to a continuum interface: held at first by the forces that
  // balance their prestress (interface_ties.h). A zoned block's tied edge
  // runs through its boundary nodes between two corners.
  first_step_ = true;
  ties_ = InterfaceTies::find(state);
  tied_edge_nodes_.clear();
  if (ties_.empty()) return;
  ties_.give_first_tractions(state);
  for (std::size_t k = 0; k < ties_.size(); ++k) {
    const auto [b, a, next] = ties_.edge(k);
    std::vector<std::pair<double, int>>& nodes = tied_edge_nodes_.emplace_back();
    const std::optional<ZonedBlock>& z = system_->blocks()[b].zoned;
    if (!z) continue;
    const std::vector<int>& loop = z->boundary()[0];
    const int from = z->corner_nodes()[a], to = z->corner_nodes()[next];
    const auto start = std::find(loop.begin(), loop.end(), from);
    FISSURE_CHECK(start != loop.end(), std::logic_error,
                  "a zoned block's corner is off its outline");
    const Vec2 p = z->positions()[from], d = z->positions()[to] - p;
    for (std::size_t i = static_cast<std::size_t>(start - loop.begin());;
         i = (i + 1) % loop.size()) {
      nodes.emplace_back(d.dot(z->positions()[loop[i]] - p) / d.squaredNorm(), loop[i]);
      if (loop[i] == to) break;
    }
  }
}

std::vector<DemTie> DemProcess::dem_ties(const std::vector<TieSpring>& springs) const {
  std::vector<DemTie> out;
  out.reserve(springs.size());
  for (const TieSpring& s : springs) {
    DemTie tie{s.block, s.a, s.b, s.t, s.force, s.target, s.stiffness};
    const std::vector<std::pair<double, int>>& nodes = tied_edge_nodes_[s.edge];
    if (!nodes.empty()) {
      // The boundary segment of the zoned block that holds the point.
      std::size_t i = 1;
      while (i + 1 < nodes.size() && nodes[i].first < s.t) ++i;
      const auto& [t0, n0] = nodes[i - 1];
      const auto& [t1, n1] = nodes[i];
      tie.a = n0;
      tie.b = n1;
      tie.t = (s.t - t0) / (t1 - t0);
    }
    out.push_back(tie);
  }
  return out;
}

std::vector<ExchangedField> DemProcess::exchanged_values(const RockMass& state) const {
  return ties_.exchanged_values(state);
}

void DemProcess::set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) {
  ties_.set_exchanged_values(state, values);
}

double DemProcess::cycle_step() const {
  if (c_.time_step) return *c_.time_step * step_scale_;
  const double critical = system_->critical_time_step();
  // No contact yet (blocks in free flight): any step integrates gravity
  // exactly; one of the rounding length's fall time keeps contacts seen.
  if (!std::isfinite(critical)) return std::sqrt(rounding_ / 9.81) * step_scale_;
  return c_.safety_factor * critical * step_scale_;
}

double DemProcess::solve_step() {
  if (!c_.density_scaling) return cycle_step();
  const double natural = system_->scale_densities();
  if (!std::isfinite(natural)) return cycle_step();  // no contact yet: nothing to scale
  return c_.safety_factor * natural * step_scale_;
}

double DemProcess::proposed_dt(const RockMass&) const {
  if (c_.solve_ratio) return std::numeric_limits<double>::infinity();
  return static_cast<double>(c_.cycles_per_step) * cycle_step();
}

void DemProcess::locate_points(const RockMass& state) {
  point_zones_.assign(state.points.size(), PointInZone{});
  const std::vector<DemBlock>& blocks = system_->blocks();
  for (std::size_t k = 0; k < state.points.size(); ++k) {
    const MaterialPoint& p = state.points[k];
    if (p.block >= 0 && blocks[p.block].zoned)
      point_zones_[k] = locate_in_zones(*blocks[p.block].zoned, p.current);
  }
}

std::vector<BlockLoad> DemProcess::external_loads(const RockMass& state, double t,
                                                  std::vector<std::vector<Vec2>>& nodal) const {
  nodal.clear();
  const std::vector<EdgePressureLoad>* pressure = state.fields.find(kPressureLoads);
  if (point_loads_.empty() && (!pressure || pressure->empty())) return {};
  std::vector<BlockLoad> loads(state.blocks.size());
  const std::vector<DemBlock>& blocks = system_->blocks();
  nodal.resize(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (blocks[b].zoned) nodal[b].assign(blocks[b].zoned->n_nodes(), Vec2::Zero());
  for (std::size_t k = 0; k < point_loads_.size(); ++k) {
    const PointLoad& l = point_loads_[k];
    if (l.block < 0) continue;
    const int point = first_load_point_ + static_cast<int>(k);
    const Vec2 at = state.points[point].current;
    const Vec2 f = history_factor(l.history, t) * l.force;
    if (blocks[l.block].zoned) {
      add_point_force(*blocks[l.block].zoned, point_zones_[point], f, nodal[l.block]);
      continue;
    }
    loads[l.block].force += f;
    loads[l.block].moment += cross(at - blocks[l.block].centroid, f);
  }
  if (pressure)
    for (const EdgePressureLoad& p : *pressure) {
      if (blocks[p.block].zoned) {
        add_edge_pressure(*blocks[p.block].zoned, p, nodal[p.block]);
        continue;
      }
      // -int p n ds over a -> b, p linear: the resultant and its moment
      // about the centroid (Simpson's rule is exact for the quadratic).
      const double length = (p.b - p.a).norm();
      const Vec2 c = blocks[p.block].centroid;
      const Vec2 mid = 0.5 * (p.a + p.b);
      const double p_mid = 0.5 * (p.p_a + p.p_b);
      loads[p.block].force += -length * p_mid * p.normal;
      loads[p.block].moment +=
          -length / 6 *
          (p.p_a * cross(p.a - c, p.normal) + 4 * p_mid * cross(mid - c, p.normal) +
           p.p_b * cross(p.b - c, p.normal));
      if (p.has_shear()) {  // +int s t ds, alike
        const Vec2 t = p.tangent();
        const double s_mid = 0.5 * (p.s_a + p.s_b);
        loads[p.block].force += length * s_mid * t;
        loads[p.block].moment +=
            length / 6 *
            (p.s_a * cross(p.a - c, t) + 4 * s_mid * cross(mid - c, t) + p.s_b * cross(p.b - c, t));
      }
    }
  return loads;
}

std::vector<double> DemProcess::apply_thermal_strain(const RockMass& state) {
  std::vector<double> factors(state.blocks.size(), 1.0);
  const std::vector<double>* strain = state.fields.find(kBlockThermalStrain);
  if (!strain) return factors;
  for (std::size_t b = 0; b < strain->size() && b < thermal_strain_.size(); ++b) {
    if (state.blocks[b].fixed || (*strain)[b] == thermal_strain_[b]) continue;
    factors[b] = (1 + (*strain)[b]) / (1 + thermal_strain_[b]);
    system_->scale_block(static_cast<int>(b), factors[b]);
    thermal_strain_[b] = (*strain)[b];
  }
  return factors;
}

StepReport DemProcess::advance(RockMass& state, double t, double dt) {
  Stopwatch clock;
  const DemSystem before = *system_;
  const std::vector<double> strain_before = thermal_strain_;
  // The velocities the coordinator left (zeroed after a quasi-static stage).
  std::vector<DemBlock>& blocks = system_->blocks();
  std::vector<Vec2> centroids;
  std::vector<double> angles;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (blocks[b].zoned) {
      // A zoned block's motion is its nodes'; the coordinator's reset (after
      // a quasi-static stage) stops them.
      if (state.blocks[b].velocity.head<3>().isZero()) blocks[b].zoned->stop();
    } else if (!blocks[b].fixed) {
      blocks[b].velocity = state.blocks[b].velocity.head<3>();
    }
    centroids.push_back(blocks[b].centroid);
    angles.push_back(edge_angle(blocks[b].polygon));
  }
  const std::vector<double> scales = apply_thermal_strain(state);
  std::vector<std::vector<Vec2>> nodal;
  system_->set_external_loads(external_loads(state, t + dt, nodal));
  system_->set_nodal_loads(std::move(nodal));
  if (first_step_ && ties_.empty())
    // The interfaces are published when the continuum initializes: a block
    // region that finds none at its own start but one now came first.
    FISSURE_CHECK(InterfaceTies::find(state).empty(), CouplingOrderError,
                  tied_before_continuum("dem", "its blocks lie along"));
  const std::vector<TieSpring> springs =
      ties_.empty() ? std::vector<TieSpring>{} : ties_.springs(state);
  system_->set_ties(dem_ties(springs));

  // Joints that stiffen under load (Bandis's hyperbola, the continuously
  // yielding law) shorten the critical step as they close: the automatic
  // step is then taken anew every cycle. Linear joints keep one step.
  const bool every_cycle = !c_.time_step && system_->stiffness_varies();
  double h = c_.solve_ratio ? solve_step() : cycle_step();
  if (c_.solve_ratio) {
    long n = 0;
    do {
      if (every_cycle && n > 0) h = solve_step();
      system_->set_time_step(h);
      system_->step();
    } while (++n < c_.max_cycles && system_->unbalanced_force_ratio() > *c_.solve_ratio);
    // The velocities of pseudo-time mean nothing in the run's time: the
    // solved state is at rest (as the coordinator's quasi_static leaves it).
    system_->stop();
  } else if (every_cycle) {
    for (double remaining = dt; remaining > 0;) {
      const double n = std::max(1.0, std::ceil(remaining / cycle_step()));
      const double step = n == 1 ? remaining : remaining / n;
      system_->set_time_step(step);
      system_->step();
      remaining = n == 1 ? 0 : remaining - step;
    }
  } else {
    const long n = std::max(1L, static_cast<long>(std::ceil(dt / h)));
    system_->set_time_step(dt / static_cast<double>(n));
    for (long k = 0; k < n; ++k) system_->step();
  }

  // Nothing non-finite leaves the process; a corner too deep is retried.
  double overlap = 0;
  for (const DemContact& c : system_->contacts()) overlap = std::max(overlap, -c.geometry.gap);
  for (const DemBlock& b : system_->blocks())
    FISSURE_CHECK(b.centroid.allFinite() && b.velocity.allFinite(), DivergenceError,
                  "a DEM block's position or velocity is not finite at t = "
                      << t + dt << " s: the cycle's step (" << h
                      << " s) is unstable for the contacts' stiffness (dem.time_step, "
                         "dem.safety_factor)");
  if (overlap > rounding_) {
    *system_ = before;
    thermal_strain_ = strain_before;
    step_scale_ *= kStepCut;
    ++counters_.retries;
    StepReport r;
    r.status = StepReport::Status::Retry;
    r.dt_retry = kStepCut * dt;
    r.reason = fmt::format(
        "two DEM blocks overlapped by {:.3g} m, more than the rounding length {:.3g} m: the "
        "cycle's step is cut to {:.3g} of its own",
        overlap, rounding_, step_scale_);
    counters_.seconds += clock.seconds();
    return r;
  }
  step_scale_ = std::min(1.0, step_scale_ * kStepGrowth);
  // Of the updates kept (a retried one is counted in its retry).
  if (c_.solve_ratio && system_->unbalanced_force_ratio() > *c_.solve_ratio)
    ++counters_.unsolved_updates;
  counters_.max_overlap = std::max(counters_.max_overlap, overlap);
  counters_.largest_ratio_at_end =
      std::max(counters_.largest_ratio_at_end, system_->unbalanced_force_ratio());
  ++counters_.updates;
  first_step_ = false;
  if (!ties_.empty()) {
    // The springs' points where the cycles left them.
    std::vector<Vec2> at;
    at.reserve(springs.size());
    for (const DemTie& tie : dem_ties(springs)) at.push_back(system_->tie_position(tie));
    ties_.give_tractions(state, springs, at);
  }
  publish(state, centroids, angles, scales);
  counters_.seconds += clock.seconds();
  return {};
}

void DemProcess::publish(RockMass& state, const std::vector<Vec2>& centroids_before,
                         const std::vector<double>& angles_before,
                         const std::vector<double>& scales) const {
  const std::vector<DemBlock>& blocks = system_->blocks();
  std::vector<double> turn(blocks.size(), 0.0);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    Block& block = state.blocks[b];
    if (block.fixed) continue;
    turn[b] = std::remainder(edge_angle(blocks[b].polygon) - angles_before[b], 2 * M_PI);
    if (const std::optional<ZonedBlock>& z = blocks[b].zoned) {
      // The block's own polygon at its corner nodes (the other processes
      // keep its vertices and edges), its stress the zones' mean.
      for (std::size_t v = 0; v < z->corner_nodes().size(); ++v)
        block.polygon.vertices[v] = z->positions()[z->corner_nodes()[v]];
      const ZoneStress s = z->mean_stress();
      block.stress = Vector3(s.xx, s.yy, s.xy);
    } else {
      block.polygon = blocks[b].polygon;
    }
    block.section = section_properties(block.polygon);
    block.velocity.setZero();
    block.velocity.head<3>() = blocks[b].velocity;
    block.rotation += turn[b];
  }
  for (std::size_t k = 0; k < state.points.size(); ++k) {
    MaterialPoint& p = state.points[k];
    if (p.block < 0 || blocks[p.block].fixed) continue;
    if (blocks[p.block].zoned) {
      p.current = position_of(*blocks[p.block].zoned, point_zones_[k]);
      continue;
    }
    p.current =
        blocks[p.block].centroid + Eigen::Rotation2Dd(turn[p.block]) *
                                       (scales[p.block] * (p.current - centroids_before[p.block]));
  }
  // Each block's average stress from its contact forces (the Love-Weber
  // sum (1/A) sum (x - c) (x) f, tension +): the stress a rigid block carries.
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (!blocks[b].fixed && !blocks[b].zoned) state.blocks[b].stress.setZero();
  for (const DemContact& c : system_->contacts()) {
    const ContactGeometry& g = c.geometry;
    const Vec2 on_i = load_on_i(g.point, g.normal, c.response.normal_stress,
                                c.response.shear_stress, g.length, blocks[g.key.block_i].centroid)
                          .force;
    for (const auto& [b, f] :
         {std::pair{g.key.block_i, on_i}, std::pair{g.key.block_j, Vec2(-on_i)}}) {
      Block& block = state.blocks[b];
      if (block.fixed || blocks[b].zoned) continue;
      const Vec2 r = g.point - blocks[b].centroid;
      block.stress += Vector3(r.x() * f.x(), r.y() * f.y(), 0.5 * (r.x() * f.y() + r.y() * f.x())) /
                      block.section.area;
    }
  }
  publish_contacts(state);
}

void DemProcess::publish_contacts(RockMass& state) const {
  std::vector<ContactRecord>& records = state.fields.get_or_add(kContacts);
  records.clear();
  records.reserve(system_->contacts().size());
  for (const DemContact& c : system_->contacts()) {
    const ContactGeometry& g = c.geometry;
    ContactRecord r;
    r.block_i = g.key.block_i;
    r.block_j = g.key.block_j;
    r.vertex = g.key.corner;
    r.edge = g.key.corner_corner() ? -1 : g.key.feature;
    r.point = g.point;
    r.normal = -g.normal;  // out of block j
    r.state = c.response.open       ? ContactState::Open
              : c.response.slipping ? ContactState::Sliding
                                    : ContactState::Locked;
    r.gap = g.gap;
    r.normal_force = c.response.normal_stress * g.length;
    r.shear_force = c.response.shear_stress * g.length;
    records.push_back(r);
  }
}

nlohmann::json DemProcess::statistics() const {
  long open = 0, sliding = 0, locked = 0;
  for (const DemContact& c : system_->contacts()) {
    if (c.response.open)
      ++open;
    else if (c.response.slipping)
      ++sliding;
    else
      ++locked;
  }
  nlohmann::json s = {
      {"method", "dem"},
      {"updates", counters_.updates},
      {"cycles", system_->cycles()},
      {"contact_searches", system_->searches()},
      {"retries", counters_.retries},
      {"unsolved_updates", counters_.unsolved_updates},
      {"unbalanced_force_ratio",
       {{"last", system_->unbalanced_force_ratio()},
        {"largest_at_an_update_end", counters_.largest_ratio_at_end}}},
      {"contacts", {{"open", open}, {"sliding", sliding}, {"locked", locked}}},
      {"critical_time_step", system_->critical_time_step()},
      {"cycle_time_step", cycle_step()},
      {"rounding", rounding_},
      {"margin", margin_},
      {"max_overlap", counters_.max_overlap},
      {"seconds", counters_.seconds},
  };
  if (c_.density_scaling)
    s["density_scaling"] = {{"largest_mass_factor", system_->largest_mass_scale()}};
  return s;
}

nlohmann::json DemProcess::energy(const RockMass&) const {
  // The ledger (dem_energy.h), but the kinetic energy of the blocks'
  // velocities as published: a quasi-static update ends at rest.
  double kinetic = 0;
  bool zoned = false;
  for (const DemBlock& b : system_->blocks())
    if (b.zoned) {
      kinetic += b.zoned->energy().kinetic;
      zoned = true;
    } else if (!b.fixed) {
      kinetic += kinetic_energy(b.body, b.velocity);
    }
  const DemEnergy ledger = system_->energy();
  nlohmann::json e = {{"kinetic", kinetic},
                      {"contacts_elastic", ledger.contacts_elastic},
                      {"gravity_work", ledger.gravity_work},
                      {"external_work", ledger.external_work},
                      {"damping_dissipated", ledger.damping_dissipated},
                      {"slip_dissipated", ledger.slip_dissipated}};
  if (zoned) e["zones_strain"] = ledger.zones_strain;
  return e;
}

template <class Self, class Archive>
void DemProcess::checkpoint(Self& self, Archive& a) {
  a("step_scale", self.step_scale_);
  a("thermal_strain", self.thermal_strain_);
  auto c = a.section("counters");
  auto& n = self.counters_;  // const when writing
  c("updates", n.updates);
  c("retries", n.retries);
  c("unsolved_updates", n.unsolved_updates);
  c("largest_ratio_at_end", n.largest_ratio_at_end);
  c("max_overlap", n.max_overlap);
  c("seconds", n.seconds);
  auto system = a.section("system");
  DemSystem::checkpoint(const_like<Self>(*self.system_), system);
}

void DemProcess::save(CheckpointWriter& out, const RockMass& state) const {
  checkpoint(*this, out);
  if (!ties_.empty())  // the tractions its blocks give the continuum
    out("interface_tractions", ties_.mortar().values(state));
}

void DemProcess::restore(CheckpointReader& in, RockMass& state) {
  // The blocks' polygons and velocities are the coordinator's; the rest,
  // with the DEM's own centroids, is the system's checkpoint.
  build_system(state);
  checkpoint(*this, in);
  locate_points(state);
  publish_contacts(state);
  first_step_ = false;
  if (!ties_.empty()) {
    std::vector<double> tractions;
    in("interface_tractions", tractions);
    ties_.mortar().set_values(state, tractions);
  }
}

}  // namespace fissure::dem
