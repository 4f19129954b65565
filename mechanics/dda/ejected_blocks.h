// Blocks thrown out by a dynamic release (docs/dda.md section 10, "Rock
// bursts"): after every accepted step, the free blocks in flight (none of
// their contacts closed) whose centroid moves faster than the ejection
// speed (mechanics.dda.ejection_speed; rock bursts eject at 1-10 m/s,
// Kaiser and Cai 2012) relative to the ground (the ground motion's
// velocity, zero without one), and their kinetic energy in the ground's
// frame (1/2 v^T M v, rotation and strain rates included). A block that
// only rings in its place (the first steps of a release) is not in flight.
// summary.json reports how many blocks were ever ejected, the largest
// speed of one, and the largest kinetic energy they held together, with
// its time.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

class EjectedBlocks {
 public:
  explicit EjectedBlocks(double speed = 1.0) : speed_(speed) {}

  /// The blocks' state at the end of an accepted step at time t, the
  /// ground moving at `ground_velocity`.
  void record(const RockMass& state, const std::vector<DdaContact>& contacts, double t,
              const Vec2& ground_velocity);
  nlohmann::json report() const;

  /// What carries over a restart (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("ejected", self.ejected_);
    a("largest_speed", self.largest_speed_);
    a("peak_kinetic_energy", self.peak_energy_);
    a("peak_time", self.peak_time_);
  }

 private:
  double speed_;
  std::vector<int> ejected_;    ///< per block: 1 once it was faster than speed_
  std::vector<char> touching_;  ///< per block, this step: a contact closed (a reused buffer)
  double largest_speed_ = 0, peak_energy_ = 0, peak_time_ = 0;
};

}  // namespace fissure::dda
