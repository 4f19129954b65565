#include "mechanics/dem/dem_system.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mechanics/dem/contact_kinematics.h"

namespace fissure::dem {

namespace {

/// The walls of a contact found in the first search touched at the start
/// (a joint of the intact rock mass) within this share of the rounding
/// length: exactly adjacent blocks' rounded corners are at a gap of
/// round-off.
constexpr double kBondedGap = 1e-6;
/// Loops shorter than this run on one thread: a cycle over a few thousand
/// contacts takes a few hundred microseconds, and on a loaded machine one
/// parallel region can wait a whole time slice for a descheduled thread
/// (the 107-block wall took 40 s instead of 3 s on two busy cores).
constexpr long kParallelFrom = 4096;

}  // namespace

DemSystem::DemSystem(std::vector<DemBlock> blocks, std::vector<joints::JointLaw> laws,
                     const DemSettings& settings)
    : blocks_(std::move(blocks)),
      laws_(std::move(laws)),
      s_(settings),
      moved_(blocks_.size(), 0),
      expansion_(blocks_.size(), 0) {
  FISSURE_CHECK(!laws_.empty(), std::invalid_argument, "the DEM needs at least one joint law");
  index_zoned_blocks();
  for (const DemBlock& b : blocks_) {
    double r = 0;
    for (const Vec2& v : b.polygon.vertices) r = std::max(r, (v - b.centroid).norm());
    radius_.push_back(r);
    for (int j : b.edge_joint)
      FISSURE_CHECK(j >= -1 && j < static_cast<int>(laws_.size()), std::invalid_argument,
                    "a block edge of joint " << j << ", of " << laws_.size() << " joints");
  }
}

void DemSystem::index_zoned_blocks() {
  const std::size_t n = blocks_.size();
  boundary_nodes_.assign(n, {});
  boundary_joints_.assign(n, {});
  every_vertex_.assign(n, 0);
  any_zoned_ = false;
  for (std::size_t b = 0; b < n; ++b) {
    if (!blocks_[b].zoned) continue;
    const ZonedBlock& z = *blocks_[b].zoned;
    any_zoned_ = true;
    every_vertex_[b] = 1;
    std::vector<int> corner_of(z.n_nodes(), -1);
    for (std::size_t k = 0; k < z.corner_nodes().size(); ++k) corner_of[z.corner_nodes()[k]] = k;
    const std::vector<int>& edge_joint = blocks_[b].edge_joint;
    for (const std::vector<int>& loop : z.boundary()) {
      // Each boundary edge lies on the block's edge from the last corner
      // node before it (the loops run as the polygon's: corner k's edge
      // ends at corner k + 1).
      const auto size = static_cast<int>(loop.size());
      int start = 0;
      while (start < size && corner_of[loop[start]] < 0) ++start;
      FISSURE_CHECK(start < size, std::invalid_argument,
                    "a boundary loop of zoned block " << b << " has no corner node");
      std::vector<int> joints(size, 0);
      for (int s = 0, edge = -1; s < size; ++s) {
        const int v = (start + s) % size;
        if (corner_of[loop[v]] >= 0) edge = corner_of[loop[v]];
        joints[v] = edge < static_cast<int>(edge_joint.size()) ? edge_joint[edge] : 0;
      }
      boundary_nodes_[b].insert(boundary_nodes_[b].end(), loop.begin(), loop.end());
      boundary_joints_[b].insert(boundary_joints_[b].end(), joints.begin(), joints.end());
    }
    // The polygon's loops are the boundary's (Polygon: {0, end of loop 0, ...}).
    Polygon& p = blocks_[b].polygon;
    p.vertices.resize(boundary_nodes_[b].size());
    p.loop_offsets.assign(1, 0);
    for (const std::vector<int>& loop : z.boundary())
      p.loop_offsets.push_back(p.loop_offsets.back() + static_cast<int>(loop.size()));
  }
  follow_zoned_nodes();
}

void DemSystem::follow_zoned_nodes() {
  if (!any_zoned_) return;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    DemBlock& block = blocks_[b];
    if (!block.zoned) continue;
    const ZonedBlock& z = *block.zoned;
    const std::vector<int>& nodes = boundary_nodes_[b];
    for (std::size_t v = 0; v < nodes.size(); ++v)
      block.polygon.vertices[v] = z.positions()[nodes[v]];
    block.centroid = z.centre_of_mass();
    block.velocity = z.mean_motion(block.centroid);
  }
}

int DemSystem::joint_of(const ContactKey& key) const {
  // A corner against an edge: the edge's joint; against a corner: the joint
  // of the edge that leaves that corner (both walls of a joint between two
  // blocks carry its name).
  const DemBlock& j = blocks_[key.block_j];
  const int edge = key.corner_corner() ? -1 - key.feature : key.feature;
  const std::vector<int>& joints = j.zoned ? boundary_joints_[key.block_j] : j.edge_joint;
  const int joint = edge < static_cast<int>(joints.size()) ? joints[edge] : 0;
  return std::max(joint, 0);
}

void DemSystem::prepare() {
  if (!started_ && searches_ == 0) locate_contacts();
}

void DemSystem::scale_block(int b, double factor) {
  DemBlock& block = blocks_[b];
  if (block.zoned) block.zoned->scale_about(block.centroid, factor);
  for (Vec2& v : block.polygon.vertices) v = block.centroid + factor * (v - block.centroid);
  block.body.inertia *= factor * factor;
  moved_[b] += std::abs(factor - 1) * radius_[b];
  radius_[b] *= factor;
  expansion_[b] = (1 + expansion_[b]) * factor - 1;
  expanded_ = true;
}

const std::vector<const Polygon*>& DemSystem::polygon_refs() {
  // Taken anew: a copy of the system (an update's rollback) holds its own.
  polygon_refs_.resize(blocks_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b) polygon_refs_[b] = &blocks_[b].polygon;
  return polygon_refs_;
}

void DemSystem::locate_contacts() {
  if (started_ && *std::max_element(moved_.begin(), moved_.end()) <= 0.25 * s_.margin) {
    const std::vector<const Polygon*>& refs = polygon_refs();
    corners_.resize(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      rounded_corners(blocks_[b].polygon, s_.rounding, corners_[b], every_vertex_[b] != 0);
    for (DemContact& c : contacts_) update_contact(c.geometry, refs, corners_);
    return;
  }
  detect();
  std::fill(moved_.begin(), moved_.end(), 0.0);
  ++searches_;
}

void DemSystem::detect() {
  std::vector<DemContact> next;
  auto old = contacts_.begin();
  for (const ContactGeometry& g :
       find_contacts(polygon_refs(), s_.rounding, s_.margin, every_vertex_)) {
    // Two fixed blocks never move: their contacts carry nothing.
    if (blocks_[g.key.block_i].fixed && blocks_[g.key.block_j].fixed) continue;
    DemContact c;
    c.geometry = g;
    old = std::lower_bound(
        old, contacts_.end(), g.key,
        [](const DemContact& a, const ContactKey& k) { return a.geometry.key < k; });
    if (old != contacts_.end() && old->geometry.key == g.key) {
      c.joint = old->joint;
      c.law = old->law;
      c.response = old->response;
      c.dashpot_normal = old->dashpot_normal;
      c.dashpot_shear = old->dashpot_shear;
    } else {
      c.joint = joint_of(g.key);
      const bool bonded = !started_ && g.gap <= kBondedGap * s_.rounding;
      c.law = laws_[c.joint].state_at(g.gap, bonded);
      c.response.open = g.gap > 0;
      if (bonded) prestress(c);
    }
    next.push_back(std::move(c));
  }
  contacts_ = std::move(next);
}

void DemSystem::prestress(DemContact& c) const {
  const ContactGeometry& g = c.geometry;
  const Eigen::Vector3d s =
      0.5 * (blocks_[g.key.block_i].initial_stress + blocks_[g.key.block_j].initial_stress);
  if (s.isZero()) return;
  // The traction on block i across the plane of normal n (from i to j):
  // sigma n; its normal part is -sigma_n (compression +), its tangential
  // part tau along t (contact_kinematics.h).
  const Vec2 n = g.normal, t = tangent_of(n);
  const Vec2 traction(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
  const double sigma_n = -traction.dot(n);
  if (!(sigma_n > 0)) return;
  const double tau = traction.dot(t);
  c.law = laws_[c.joint].prestressed_state(g.gap, sigma_n, tau, g.length);
  c.response.normal_stress = sigma_n;
  c.response.shear_stress = tau;
  c.response.open = false;
  // A shear stress beyond the joint's strength (a stress state that makes
  // the joint slip, as in a REV study under stress) starts at the strength:
  // the law's step without motion maps it back, and the blocks then move.
  joints::JointLaw::State admissible = c.law;
  const joints::JointResponse start = laws_[c.joint].update(c.law, {0, 0, g.length}, admissible);
  if (start.slipping) {
    c.law = admissible;
    c.response = start;
  }
}

double DemSystem::edge_weight(const ContactGeometry& g) const {
  const Polygon& p = blocks_[g.key.block_j].polygon;
  const Vec2& a = p.vertices[g.key.feature];
  const Vec2 edge = p.vertices[p.next(g.key.feature)] - a;
  return std::clamp((g.point - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
}

Vec2 DemSystem::wall_velocity(int b, const ContactGeometry& g, bool side_i, double weight) const {
  const DemBlock& block = blocks_[b];
  if (!block.zoned) return point_velocity(block.velocity, block.centroid, g.point);
  const std::vector<Vec2>& v = block.zoned->velocities();
  if (side_i) return v[node_of(b, g.key.corner)];
  if (g.key.corner_corner()) return v[node_of(b, -1 - g.key.feature)];
  const int e = g.key.feature;
  return (1 - weight) * v[node_of(b, e)] + weight * v[node_of(b, block.polygon.next(e))];
}

std::vector<BlockLoad> DemSystem::contact_loads(bool advance_laws) {
  const auto n = static_cast<long>(contacts_.size());
  on_i_.resize(n);
  on_j_.resize(n);
  if (any_zoned_) edge_weight_.assign(n, 0.0);
  if (advance_laws) {
    spring_work_.assign(n, 0.0);
    dashpot_work_.assign(n, 0.0);
    expansion_work_.assign(n, 0.0);
  }
  const bool dashpots = s_.stiffness_damping > 0;
  // Every contact on its own: stresses and loads into its own slots.
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long k = 0; k < n; ++k) {
    DemContact& c = contacts_[k];
    const ContactGeometry& g = c.geometry;
    const DemBlock& bi = blocks_[g.key.block_i];
    const DemBlock& bj = blocks_[g.key.block_j];
    const bool zoned = bi.zoned || bj.zoned;
    if (bj.zoned && !g.key.corner_corner()) edge_weight_[k] = edge_weight(g);
    if (advance_laws) {
      DisplacementIncrement d =
          zoned ? relative_displacement(g.normal, wall_velocity(g.key.block_i, g, true, 0),
                                        wall_velocity(g.key.block_j, g, false, edge_weight_[k]),
                                        last_step_)
                : relative_displacement(g.point, g.normal, bi.velocity, bi.centroid, bj.velocity,
                                        bj.centroid, last_step_);
      const DisplacementIncrement motion = d;
      DisplacementIncrement expansion;
      if (expanded_) {
        // The walls' move by the blocks' expansion since the laws' last
        // step (scale_block): e (x - c) of each block at the contact point.
        const Vec2 du = expansion_[g.key.block_j] * (g.point - bj.centroid) -
                        expansion_[g.key.block_i] * (g.point - bi.centroid);
        expansion = {du.dot(g.normal), du.dot(tangent_of(g.normal))};
        d.normal += expansion.normal;
        d.shear += expansion.shear;
      }
      const joints::JointResponse before = c.response;
      joints::JointLaw::State after = c.law;
      c.response = laws_[c.joint].update(c.law, {d.normal, d.shear, g.length}, after);
      c.law = std::move(after);
      const double sn = c.response.normal_stress, ss = c.response.shear_stress;
      spring_work_[k] =
          contact_work(before.normal_stress, before.shear_stress, sn, ss, d, g.length);
      if (expanded_)
        expansion_work_[k] =
            contact_work(before.normal_stress, before.shear_stress, sn, ss, expansion, g.length);
      if (dashpots) {
        const double dn = c.dashpot_normal, ds = c.dashpot_shear;
        update_dashpots(c, motion);
        dashpot_work_[k] =
            contact_work(dn, ds, c.dashpot_normal, c.dashpot_shear, motion, g.length);
      }
    }
    double sn = c.response.normal_stress, ss = c.response.shear_stress;
    if (dashpots) {
      sn += c.dashpot_normal;
      ss += c.dashpot_shear;
    }
    on_i_[k] = load_on_i(g.point, g.normal, sn, ss, g.length, bi.centroid);
    on_j_[k] = load_on_j(g.point, g.normal, sn, ss, g.length, bj.centroid);
  }
  if (advance_laws) {
    // The ledger's sums in the contacts' order (the same on any threads).
    for (long k = 0; k < n; ++k) {
      contact_work_ += spring_work_[k];
      dashpot_dissipated_ += dashpot_work_[k];
      expansion_work_sum_ += expansion_work_[k];
    }
  }
  if (advance_laws && expanded_) {
    std::fill(expansion_.begin(), expansion_.end(), 0.0);
    expanded_ = false;
  }
  // ... summed per block (or node) in the contacts' order (reproducible to
  // the bit).
  std::vector<BlockLoad> loads(blocks_.size());
  for (long k = 0; k < n; ++k) {
    const ContactKey& key = contacts_[k].geometry.key;
    if (ZonedBlock* z = zoned_of(key.block_i)) {
      z->add_contact_force(node_of(key.block_i, key.corner), on_i_[k].force);
    } else {
      loads[key.block_i].force += on_i_[k].force;
      loads[key.block_i].moment += on_i_[k].moment;
    }
    if (ZonedBlock* z = zoned_of(key.block_j)) {
      if (key.corner_corner()) {
        z->add_contact_force(node_of(key.block_j, -1 - key.feature), on_j_[k].force);
      } else {
        const double w = edge_weight_[k];
        const int e = key.feature;
        z->add_contact_force(node_of(key.block_j, e), (1 - w) * on_j_[k].force);
        z->add_contact_force(node_of(key.block_j, blocks_[key.block_j].polygon.next(e)),
                             w * on_j_[k].force);
      }
    } else {
      loads[key.block_j].force += on_j_[k].force;
      loads[key.block_j].moment += on_j_[k].moment;
    }
  }
  return loads;
}

void DemSystem::update_dashpots(DemContact& c, const DisplacementIncrement& du) const {
  // Rayleigh's stiffness-proportional term on the contact's springs: the
  // stress rate beta k du/dt of the closed contact, the shear one only
  // while it sticks (a slipping contact's shear stress is its strength,
  // which a dashpot would raise).
  c.dashpot_normal = c.dashpot_shear = 0;
  if (c.response.open || !(last_step_ > 0)) return;
  const joints::JointStiffness k =
      laws_[c.joint].stiffness(c.response.normal_stress, c.geometry.length);
  const double rate = s_.stiffness_damping / last_step_;
  c.dashpot_normal = -rate * k.normal * du.normal;
  if (!c.response.slipping) c.dashpot_shear = rate * k.shear * du.shear;
}

double DemSystem::contacts_elastic_energy() const {
  double stored = 0;
  for (const DemContact& c : contacts_)
    stored += contact_elastic_energy(laws_[c.joint], c.response.normal_stress,
                                     c.response.shear_stress, c.geometry.length);
  return stored;
}

DemEnergy DemSystem::energy() const {
  DemEnergy e;
  e.kinetic = kinetic_;
  if (!started_) {
    e.kinetic = 0;
    for (const DemBlock& b : blocks_)
      if (!b.fixed && !b.zoned) e.kinetic += kinetic_energy(b.body, b.velocity);
  }
  e.gravity_work = gravity_work_.at_cycle_time();
  e.external_work = applied_work_.at_cycle_time() + expansion_work_sum_;
  e.damping_dissipated = damping_dissipated_.at_cycle_time() + dashpot_dissipated_;
  e.contacts_elastic = contacts_elastic_energy();
  e.slip_dissipated = started_ ? contact_work_ - (e.contacts_elastic - stored_at_start_) : 0.0;
  for (const DemBlock& b : blocks_) {
    if (!b.zoned) continue;
    // The zones' own balance, less the contacts' work on the nodes (the
    // contacts' side holds it).
    const EnergyBalance z = b.zoned->energy();
    e.kinetic += z.kinetic;
    e.zones_strain += z.strain;
    e.damping_dissipated += z.dissipated;
    e.gravity_work += z.gravity_work;
    e.external_work += z.external_work - z.gravity_work - z.contact_work;
  }
  return e;
}

void DemSystem::stop() {
  // The motion a stop takes away (a quasi-static solve's pseudo-time
  // motion) counts as damped.
  damping_dissipated_.add_whole(kinetic_);
  kinetic_ = 0;
  for (DemBlock& b : blocks_) {
    b.velocity.setZero();
    if (b.zoned) b.zoned->stop();
  }
}

Vec2 DemSystem::tie_position(const DemTie& tie) const {
  const DemBlock& block = blocks_[tie.block];
  if (block.zoned) {
    const std::vector<Vec2>& x = block.zoned->positions();
    return (1 - tie.t) * x[tie.a] + tie.t * x[tie.b];
  }
  const std::vector<Vec2>& v = block.polygon.vertices;
  return (1 - tie.t) * v[tie.a] + tie.t * v[tie.b];
}

void DemSystem::add_tie_loads(std::vector<BlockLoad>& applied) const {
  for (const DemTie& tie : ties_) {
    if (blocks_[tie.block].zoned) continue;
    const Vec2 x = tie_position(tie);
    const Vec2 f = tie.force + tie.stiffness * (tie.target - x);
    const Vec2 r = x - blocks_[tie.block].centroid;
    applied[tie.block].force += f;
    applied[tie.block].moment += r.x() * f.y() - r.y() * f.x();
  }
}

void DemSystem::move_zoned_blocks() {
  const auto n = static_cast<long>(blocks_.size());
  long zones = 0;
  for (const DemBlock& b : blocks_) zones += b.zoned ? b.zoned->n_zones() : 0;
  // The ties' forces at the nodes' present positions x^n, shared by the
  // two nodes the point lies between.
  for (const DemTie& tie : ties_) {
    if (!blocks_[tie.block].zoned) continue;
    const Vec2 f = tie.force + tie.stiffness * (tie.target - tie_position(tie));
    blocks_[tie.block].zoned->add_force(tie.a, (1 - tie.t) * f);
    blocks_[tie.block].zoned->add_force(tie.b, tie.t * f);
  }
  // The zones' strain is the last half step's velocities over the step that
  // moved the nodes (none before the first step).
#pragma omp parallel for schedule(dynamic) if (zones >= kParallelFrom)
  for (long b = 0; b < n; ++b) {
    DemBlock& block = blocks_[b];
    if (!block.zoned) continue;
    ZonedBlock& z = *block.zoned;
    if (b < static_cast<long>(nodal_.size()))
      for (std::size_t a = 0; a < nodal_[b].size(); ++a)
        z.add_force(static_cast<int>(a), nodal_[b][a]);
    z.update_zones(started_ ? last_step_ : s_.time_step, s_.stiffness_damping);
    z.move_nodes(s_.time_step, s_.gravity, s_.damping);
    double fastest = 0;
    for (const Vec2& v : z.velocities()) fastest = std::max(fastest, v.squaredNorm());
    moved_[b] += std::sqrt(fastest) * s_.time_step;
  }
  follow_zoned_nodes();
}

void DemSystem::step() {
  locate_contacts();
  if (!started_) stored_at_start_ = contacts_elastic_energy();
  std::vector<BlockLoad> loads = contact_loads(started_);
  // The ratio's denominator: the magnitudes of the forces on each free block.
  std::vector<double> magnitude(blocks_.size(), 0.0);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const ContactKey& key = contacts_[k].geometry.key;
    magnitude[key.block_i] += on_i_[k].force.norm();
    magnitude[key.block_j] += on_j_[k].force.norm();
  }
  const auto n = static_cast<long>(blocks_.size());
  std::vector<double> unbalanced(n, 0.0);
  block_energy_.assign(n, RigidStepEnergy{});
  // Loads besides the contacts': the held ones and the ties' of this cycle.
  std::vector<BlockLoad> with_ties;
  if (!ties_.empty()) {
    with_ties = external_;
    with_ties.resize(blocks_.size());
    add_tie_loads(with_ties);
  }
  const std::vector<BlockLoad>& besides = ties_.empty() ? external_ : with_ties;
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long b = 0; b < n; ++b) {
    DemBlock& block = blocks_[b];
    if (block.fixed || block.zoned) continue;
    BlockLoad& load = loads[b];
    const BlockLoad applied = besides.empty() ? BlockLoad{} : besides[b];
    if (!besides.empty()) {
      load.force += besides[b].force;
      load.moment += besides[b].moment;
      magnitude[b] += besides[b].force.norm();
    }
    const Vec2 weight = block.body.mass * s_.gravity;
    magnitude[b] += weight.norm();
    unbalanced[b] = (load.force + weight).norm();
    const RigidBody& inertial = inertial_.empty() ? block.body : inertial_[b];
    if (!started_)
      block.velocity = velocity_before_first_step(block.velocity, block.body, inertial, load,
                                                  s_.gravity, s_.time_step);
    const Motion before = block.velocity;
    const Motion increment =
        advance(block.velocity, block.body, inertial, load, s_.gravity, s_.time_step, s_.damping);
    block_energy_[b] =
        rigid_step_energy(block.body, inertial, before, block.velocity, load, applied, s_.gravity,
                          s_.time_step, s_.damping.local > 0 || s_.damping.mass > 0);
    move_rigidly(block.polygon, block.centroid, increment);
    moved_[b] += increment.head<2>().norm() + std::abs(increment.z()) * radius_[b];
  }
  double kinetic = 0, gravity = 0, applied = 0, dissipated = 0;
  for (const RigidStepEnergy& e : block_energy_) {
    kinetic += e.kinetic;
    gravity += e.gravity;
    applied += e.applied;
    dissipated += e.dissipated;
  }
  kinetic_ = kinetic;
  gravity_work_.add(gravity);
  applied_work_.add(applied);
  damping_dissipated_.add(dissipated);
  if (any_zoned_) move_zoned_blocks();
  // The ratio over the rigid blocks and the zoned blocks' nodes alike.
  double largest = 0, sum = 0;
  long free_blocks = 0;
  for (long b = 0; b < n; ++b) {
    if (blocks_[b].fixed || blocks_[b].zoned) continue;
    largest = std::max(largest, unbalanced[b]);
    sum += magnitude[b];
    ++free_blocks;
  }
  for (const DemBlock& b : blocks_)
    if (b.zoned) {
      const UnbalancedForce& u = b.zoned->unbalanced_force();
      largest = std::max(largest, u.largest);
      sum += u.mean_applied * b.zoned->n_nodes();
      free_blocks += b.zoned->n_nodes();
    }
  ratio_ = sum > 0 ? largest / (sum / static_cast<double>(free_blocks)) : 0;
  started_ = true;
  last_step_ = s_.time_step;
  time_ += s_.time_step;
  ++cycles_;
}

}  // namespace fissure::dem
