// The DEM cycle's stable step (docs/dem.md section 2): the stiffness each
// free block's motion meets from its contacts, the critical step of every
// block on it (rigid: 2 sqrt(m/k) and its rotation's; zoned: its zones'
// and its nodes' contacts), and density scaling, which raises the blocks'
// inertia until they share the largest natural step. Part of DemSystem
// (dem_system.h); the cycle itself is dem_system.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "mechanics/dem/dem_system.h"

namespace fissure::dem {

bool DemSystem::stiffness_varies() const {
  return std::any_of(laws_.begin(), laws_.end(), [](const joints::JointLaw& law) {
    return law.kind() != joints::JointModelKind::Coulomb;
  });
}

std::vector<DemSystem::BlockStiffness> DemSystem::block_stiffnesses() const {
  std::vector<BlockStiffness> out(blocks_.size());
  // A zoned block's nodes: each takes the whole k L of its contacts (an
  // edge's two nodes both, an upper bound of their shares).
  std::vector<std::vector<double>> k_node(blocks_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    if (blocks_[b].zoned) k_node[b].assign(blocks_[b].zoned->n_nodes(), 0.0);
  for (const DemContact& c : contacts_) {
    const joints::JointStiffness s =
        laws_[c.joint].stiffness(c.response.normal_stress, c.geometry.length);
    const double kl = std::max(s.normal, s.shear) * c.geometry.length;
    const ContactKey& key = c.geometry.key;
    for (int b : {key.block_i, key.block_j}) {
      if (blocks_[b].zoned) {
        const Polygon& p = blocks_[b].polygon;
        if (b == key.block_i) {
          k_node[b][node_of(b, key.corner)] += kl;
        } else if (key.corner_corner()) {
          k_node[b][node_of(b, -1 - key.feature)] += kl;
        } else {
          k_node[b][node_of(b, key.feature)] += kl;
          k_node[b][node_of(b, p.next(key.feature))] += kl;
        }
        continue;
      }
      out[b].k += kl;
      out[b].k_rot += kl * (c.geometry.point - blocks_[b].centroid).squaredNorm();
    }
  }
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    if (const std::optional<ZonedBlock>& z = blocks_[b].zoned)
      for (int a = 0; a < z->n_nodes(); ++a)
        out[b].node_omega2 = std::max(out[b].node_omega2, k_node[b][a] / z->masses()[a]);
  return out;
}

double DemSystem::block_critical_step(std::size_t b, const BlockStiffness& s) const {
  if (const std::optional<ZonedBlock>& z = blocks_[b].zoned)
    return 2 / std::sqrt(z->zones_omega_squared() + s.node_omega2);
  const RigidBody& body = blocks_[b].body;
  return std::min(dem::critical_time_step(body.mass, s.k),
                  dem::critical_time_step(body.inertia, s.k_rot));
}

double DemSystem::critical_time_step() const {
  const std::vector<BlockStiffness> k = block_stiffnesses();
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (blocks_[b].fixed && !blocks_[b].zoned) continue;
    double step = block_critical_step(b, k[b]);
    // With density scaling, the raised inertia's step.
    if (!inertial_.empty() && !blocks_[b].zoned)
      step = std::min(dem::critical_time_step(inertial_[b].mass, k[b].k),
                      dem::critical_time_step(inertial_[b].inertia, k[b].k_rot));
    else if (!inertial_.empty())
      step *= std::sqrt(mass_scale_[b]);
    dt = std::min(dt, step);
  }
  return damped_critical_time_step(dt, s_.stiffness_damping);
}

double DemSystem::scale_densities() {
  const std::vector<BlockStiffness> k = block_stiffnesses();
  double target = 0;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (blocks_[b].fixed && !blocks_[b].zoned) continue;
    const double step = block_critical_step(b, k[b]);
    if (std::isfinite(step)) target = std::max(target, step);
  }
  inertial_.clear();
  mass_scale_.assign(blocks_.size(), 1.0);
  largest_mass_scale_ = 1;
  if (!(target > 0)) {
    for (DemBlock& b : blocks_)
      if (b.zoned) b.zoned->set_inertial_masses({});
    return std::numeric_limits<double>::infinity();
  }
  // Stable at T where 2 sqrt(m' / k) >= T: m' = max(m, k T^2 / 4).
  const double quarter_t2 = 0.25 * target * target;
  inertial_.resize(blocks_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    DemBlock& block = blocks_[b];
    if (block.zoned) {
      // One factor for all of a block's nodes: its zones' frequencies and
      // its nodes' contacts' both fall by it (the bound of
      // critical_time_step, scaled).
      ZonedBlock& z = *block.zoned;
      const double factor =
          std::max(1.0, (z.zones_omega_squared() + k[b].node_omega2) * quarter_t2);
      std::vector<double> masses = z.masses();
      for (double& m : masses) m *= factor;
      z.set_inertial_masses(std::move(masses));
      mass_scale_[b] = factor;
    } else {
      const RigidBody& body = block.body;
      inertial_[b] = {std::max(body.mass, k[b].k * quarter_t2),
                      std::max(body.inertia, k[b].k_rot * quarter_t2)};
      if (!block.fixed)
        mass_scale_[b] =
            std::max(inertial_[b].mass / body.mass, inertial_[b].inertia / body.inertia);
    }
    largest_mass_scale_ = std::max(largest_mass_scale_, mass_scale_[b]);
  }
  return target;
}

}  // namespace fissure::dem
