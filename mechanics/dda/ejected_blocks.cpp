#include "mechanics/dda/ejected_blocks.h"

#include <algorithm>

#include "mechanics/dda/block_kinematics.h"

namespace fissure::dda {

void EjectedBlocks::record(const RockMass& state, const std::vector<DdaContact>& contacts, double t,
                           const Vec2& ground_velocity) {
  ejected_.resize(state.blocks.size(), 0);
  touching_.assign(state.blocks.size(), 0);
  for (const DdaContact& c : contacts)
    if (c.state != ContactState::Open) touching_[c.key.block_i] = touching_[c.key.block_j] = 1;
  double energy = 0;
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    const Block& block = state.blocks[b];
    if (block.fixed || touching_[b]) continue;
    Vector6 v = block.velocity;
    v.head<2>() -= ground_velocity;
    const double speed = v.head<2>().norm();
    largest_speed_ = std::max(largest_speed_, speed);
    if (speed <= speed_) continue;
    ejected_[b] = 1;
    energy += kinetic_energy(block, state.materials[block.material].density, v);
  }
  if (energy > peak_energy_) {
    peak_energy_ = energy;
    peak_time_ = t;
  }
}

nlohmann::json EjectedBlocks::report() const {
  return {{"speed", speed_},
          {"blocks", std::count(ejected_.begin(), ejected_.end(), 1)},
          {"largest_speed", largest_speed_},
          {"peak_kinetic_energy", peak_energy_},
          {"peak_time", peak_time_}};
}

}  // namespace fissure::dda
