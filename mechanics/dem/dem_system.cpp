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
  for (const DemBlock& b : blocks_) {
    double r = 0;
    for (const Vec2& v : b.polygon.vertices) r = std::max(r, (v - b.centroid).norm());
    radius_.push_back(r);
    for (int j : b.edge_joint)
      FISSURE_CHECK(j >= -1 && j < static_cast<int>(laws_.size()), std::invalid_argument,
                    "a block edge of joint " << j << ", of " << laws_.size() << " joints");
  }
}

int DemSystem::joint_of(const ContactKey& key) const {
  // A corner against an edge: the edge's joint; against a corner: the joint
  // of the edge that leaves that corner (both walls of a joint between two
  // blocks carry its name).
  const DemBlock& j = blocks_[key.block_j];
  const int edge = key.corner_corner() ? -1 - key.feature : key.feature;
  const int joint = edge < static_cast<int>(j.edge_joint.size()) ? j.edge_joint[edge] : 0;
  return std::max(joint, 0);
}

void DemSystem::prepare() {
  if (!started_ && searches_ == 0) locate_contacts();
}

void DemSystem::scale_block(int b, double factor) {
  DemBlock& block = blocks_[b];
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
      rounded_corners(blocks_[b].polygon, s_.rounding, corners_[b]);
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
  for (const ContactGeometry& g : find_contacts(polygon_refs(), s_.rounding, s_.margin)) {
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
}

std::vector<BlockLoad> DemSystem::contact_loads(bool advance_laws) {
  const auto n = static_cast<long>(contacts_.size());
  on_i_.resize(n);
  on_j_.resize(n);
  // Every contact on its own: stresses and loads into its own slots.
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long k = 0; k < n; ++k) {
    DemContact& c = contacts_[k];
    const ContactGeometry& g = c.geometry;
    const DemBlock& bi = blocks_[g.key.block_i];
    const DemBlock& bj = blocks_[g.key.block_j];
    if (advance_laws) {
      DisplacementIncrement d = relative_displacement(g.point, g.normal, bi.velocity, bi.centroid,
                                                      bj.velocity, bj.centroid, last_step_);
      if (expanded_) {
        // The walls' move by the blocks' expansion since the laws' last
        // step (scale_block): e (x - c) of each block at the contact point.
        const Vec2 du = expansion_[g.key.block_j] * (g.point - bj.centroid) -
                        expansion_[g.key.block_i] * (g.point - bi.centroid);
        d.normal += du.dot(g.normal);
        d.shear += du.dot(tangent_of(g.normal));
      }
      joints::JointLaw::State after = c.law;
      c.response = laws_[c.joint].update(c.law, {d.normal, d.shear, g.length}, after);
      c.law = std::move(after);
    }
    const double sn = c.response.normal_stress, ss = c.response.shear_stress;
    on_i_[k] = load_on_i(g.point, g.normal, sn, ss, g.length, bi.centroid);
    on_j_[k] = load_on_j(g.point, g.normal, sn, ss, g.length, bj.centroid);
  }
  if (advance_laws && expanded_) {
    std::fill(expansion_.begin(), expansion_.end(), 0.0);
    expanded_ = false;
  }
  // ... summed per block in the contacts' order (reproducible to the bit).
  std::vector<BlockLoad> loads(blocks_.size());
  for (long k = 0; k < n; ++k) {
    const ContactKey& key = contacts_[k].geometry.key;
    loads[key.block_i].force += on_i_[k].force;
    loads[key.block_i].moment += on_i_[k].moment;
    loads[key.block_j].force += on_j_[k].force;
    loads[key.block_j].moment += on_j_[k].moment;
  }
  return loads;
}

void DemSystem::step() {
  locate_contacts();
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
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long b = 0; b < n; ++b) {
    DemBlock& block = blocks_[b];
    if (block.fixed) continue;
    BlockLoad& load = loads[b];
    if (!external_.empty()) {
      load.force += external_[b].force;
      load.moment += external_[b].moment;
      magnitude[b] += external_[b].force.norm();
    }
    const Vec2 weight = block.body.mass * s_.gravity;
    magnitude[b] += weight.norm();
    unbalanced[b] = (load.force + weight).norm();
    if (!started_)
      block.velocity =
          velocity_before_first_step(block.velocity, block.body, load, s_.gravity, s_.time_step);
    const Motion increment =
        advance(block.velocity, block.body, load, s_.gravity, s_.time_step, s_.damping);
    move_rigidly(block.polygon, block.centroid, increment);
    moved_[b] += increment.head<2>().norm() + std::abs(increment.z()) * radius_[b];
  }
  double largest = 0, sum = 0;
  long free_blocks = 0;
  for (long b = 0; b < n; ++b) {
    if (blocks_[b].fixed) continue;
    largest = std::max(largest, unbalanced[b]);
    sum += magnitude[b];
    ++free_blocks;
  }
  ratio_ = sum > 0 ? largest / (sum / static_cast<double>(free_blocks)) : 0;
  started_ = true;
  last_step_ = s_.time_step;
  time_ += s_.time_step;
  ++cycles_;
}

bool DemSystem::stiffness_varies() const {
  return std::any_of(laws_.begin(), laws_.end(), [](const joints::JointLaw& law) {
    return law.kind() != joints::JointModelKind::Coulomb;
  });
}

double DemSystem::critical_time_step() const {
  std::vector<double> k(blocks_.size(), 0.0), k_rot(blocks_.size(), 0.0);
  for (const DemContact& c : contacts_) {
    const joints::JointStiffness s =
        laws_[c.joint].stiffness(c.response.normal_stress, c.geometry.length);
    const double kl = std::max(s.normal, s.shear) * c.geometry.length;
    for (int b : {c.geometry.key.block_i, c.geometry.key.block_j}) {
      k[b] += kl;
      k_rot[b] += kl * (c.geometry.point - blocks_[b].centroid).squaredNorm();
    }
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (blocks_[b].fixed) continue;
    if (k[b] > 0) dt = std::min(dt, dem::critical_time_step(blocks_[b].body.mass, k[b]));
    if (k_rot[b] > 0) dt = std::min(dt, dem::critical_time_step(blocks_[b].body.inertia, k_rot[b]));
  }
  return dt;
}

}  // namespace fissure::dem
