// The viscosity of the water in each fracture segment: the flow's reader of
// the shared field "fracture_fluid_temperature" (rockmass/fields/
// fracture_temperature.h; theory.md 6.3, T -> H). With the field, a segment's
// cubic-law conductance uses mu(T_segment) of Kestin et al.
// (flow/network/water_viscosity.h); without it, the fluid's constant
// viscosity, to the bit as before.
//
// Where the water is not the correlation's liquid at the fracture's pressure
// (below 0 C, or above its boiling point at the segment's mean absolute
// pressure) the flow goes on with the correlation's value and counts the
// segments; summary.json reports them with a warning
// (processes.flow.viscosity). A temperature outside the correlation's range
// (-8..150 C) or not finite ends the run (DivergenceError) naming the
// segment: never a NaN viscosity.
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rockmass/fracture_graph.h"

namespace fissure::flow {

class SegmentViscosity {
 public:
  /// Per segment mu (Pa s) from the segments' water temperatures (degC).
  /// Throws std::logic_error when the field does not have one value per
  /// segment, DivergenceError for a temperature without a viscosity.
  void update(const FractureGraph& graph, const std::vector<double>& temperature,
              std::vector<double>& viscosity);
  /// Checks the water's state at the published node pressures (gauge, Pa)
  /// and counts the segments where it is not liquid.
  void check_state(const FractureGraph& graph, const std::vector<double>& temperature,
                   const std::vector<double>& pressure);
  /// Whether a temperature field was ever read.
  bool used() const { return counters_.updates > 0; }
  /// processes.flow.viscosity of summary.json (only when used).
  nlohmann::json statistics() const;

  /// The counters (core/io/checkpoint.h); nothing before a field was read.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    if constexpr (Archive::reading) {
      self.counters_ = {};
      self.warning_.clear();
      if (!a.has("viscosity_updates")) return;
    } else if (!self.used()) {
      return;
    }
    a("viscosity_updates", self.counters_.updates);
    a("viscosity_lowest_temperature", self.counters_.lowest);
    a("viscosity_highest_temperature", self.counters_.highest);
    a("viscosity_supercooled", self.counters_.supercooled);
    a("viscosity_boiling", self.counters_.boiling);
    a("viscosity_warning", self.warning_);
  }

 private:
  struct Counters {
    long updates = 0;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    /// Segment checks (summed over updates) that found supercooled or boiling water.
    long supercooled = 0, boiling = 0;
  } counters_;
  std::string warning_;  ///< the first, for summary.json
};

}  // namespace fissure::flow
