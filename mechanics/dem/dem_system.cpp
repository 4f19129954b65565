#include "mechanics/dem/dem_system.h"

#include <algorithm>
#include <cmath>

#include "mechanics/dem/contact_kinematics.h"

namespace fissure::dem {

DemSystem::DemSystem(std::vector<DemBlock> blocks, const joints::CoulombProperties& joint,
                     const DemSettings& settings)
    : blocks_(std::move(blocks)), law_(joint), s_(settings), moved_(blocks_.size(), 0) {
  for (const DemBlock& b : blocks_) {
    double r = 0;
    for (const Vec2& v : b.polygon.vertices) r = std::max(r, (v - b.centroid).norm());
    radius_.push_back(r);
  }
}

void DemSystem::locate_contacts() {
  if (started_ && *std::max_element(moved_.begin(), moved_.end()) <= 0.25 * s_.margin) {
    std::vector<Polygon> polygons;
    for (const DemBlock& b : blocks_) polygons.push_back(b.polygon);
    std::vector<ContactGeometry> geometry;
    for (const DemContact& c : contacts_) geometry.push_back(c.geometry);
    update_contacts(geometry, polygons, s_.rounding);
    for (std::size_t k = 0; k < contacts_.size(); ++k) contacts_[k].geometry = geometry[k];
    return;
  }
  detect();
  std::fill(moved_.begin(), moved_.end(), 0.0);
  ++searches_;
}

void DemSystem::detect() {
  std::vector<Polygon> polygons;
  for (const DemBlock& b : blocks_) polygons.push_back(b.polygon);
  std::vector<DemContact> next;
  auto old = contacts_.begin();
  for (const ContactGeometry& g : find_contacts(polygons, s_.rounding, s_.margin)) {
    DemContact c;
    c.geometry = g;
    old = std::lower_bound(
        old, contacts_.end(), g.key,
        [](const DemContact& a, const ContactKey& k) { return a.geometry.key < k; });
    if (old != contacts_.end() && old->geometry.key == g.key) {
      c.law = old->law;
    } else {
      c.law = law_.initial_state();
      c.law.normal_displacement = g.gap;
      c.law.intact = false;
    }
    next.push_back(c);
  }
  contacts_ = std::move(next);
}

std::vector<BlockLoad> DemSystem::contact_loads() {
  std::vector<BlockLoad> loads(blocks_.size());
  for (DemContact& c : contacts_) {
    const ContactGeometry& g = c.geometry;
    const DemBlock& bi = blocks_[g.key.block_i];
    const DemBlock& bj = blocks_[g.key.block_j];
    if (started_) {
      const DisplacementIncrement d = relative_displacement(
          g.point, g.normal, bi.velocity, bi.centroid, bj.velocity, bj.centroid, s_.time_step);
      joints::CoulombSlip::State after;
      const joints::JointResponse r = law_.update(c.law, {d.normal, d.shear, g.length}, after);
      c.law = after;
      c.normal_stress = r.normal_stress;
      c.shear_stress = r.shear_stress;
    }
    const BlockLoad on_i =
        load_on_i(g.point, g.normal, c.normal_stress, c.shear_stress, g.length, bi.centroid);
    const BlockLoad on_j =
        load_on_j(g.point, g.normal, c.normal_stress, c.shear_stress, g.length, bj.centroid);
    loads[g.key.block_i].force += on_i.force;
    loads[g.key.block_i].moment += on_i.moment;
    loads[g.key.block_j].force += on_j.force;
    loads[g.key.block_j].moment += on_j.moment;
  }
  return loads;
}

void DemSystem::step() {
  locate_contacts();
  const std::vector<BlockLoad> loads = contact_loads();
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    DemBlock& block = blocks_[b];
    if (block.fixed) continue;
    if (!started_)
      block.velocity = velocity_before_first_step(block.velocity, block.body, loads[b], s_.gravity,
                                                  s_.time_step);
    const Motion increment =
        advance(block.velocity, block.body, loads[b], s_.gravity, s_.time_step, s_.damping);
    move_rigidly(block.polygon, block.centroid, increment);
    moved_[b] += increment.head<2>().norm() + std::abs(increment.z()) * radius_[b];
  }
  started_ = true;
  time_ += s_.time_step;
}

}  // namespace fissure::dem
