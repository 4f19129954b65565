#include "flow/cubic_law/segment_viscosity.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "flow/network/water_viscosity.h"
#include "rockmass/fields/fracture_temperature.h"

namespace fissure::flow {

namespace {

std::string where(const FractureGraph& g, int s) {
  const Vec2 mid = 0.5 * (g.nodes[g.segments[s].node_a] + g.nodes[g.segments[s].node_b]);
  return fmt::format("fracture segment {} at ({:g}, {:g}) m", s, mid.x(), mid.y());
}

}  // namespace

void SegmentViscosity::update(const FractureGraph& g, const std::vector<double>& temperature,
                              std::vector<double>& viscosity) {
  const int m = g.n_segments();
  FISSURE_CHECK(static_cast<int>(temperature.size()) == m, std::logic_error,
                "the field '" << kFractureFluidTemperature.name << "' has " << temperature.size()
                              << " values for " << m << " fracture segments");
  viscosity.resize(m);
  for (int s = 0; s < m; ++s) {
    const double t = temperature[s];
    FISSURE_CHECK(water_state(t, kAtmosphericPressure) != WaterState::OutsideCorrelation,
                  DivergenceError,
                  "flow: water at " << t << " C in " << where(g, s)
                                    << " is outside the range of the viscosity correlation ("
                                    << kWaterViscosityLowest << " to " << kWaterViscosityHighest
                                    << " C, Kestin et al. 1978; docs/flow.md)");
    viscosity[s] = water_viscosity(t);
    counters_.lowest = std::min(counters_.lowest, t);
    counters_.highest = std::max(counters_.highest, t);
  }
  ++counters_.updates;
}

void SegmentViscosity::check_state(const FractureGraph& g, const std::vector<double>& temperature,
                                   const std::vector<double>& pressure) {
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    const double p = kAtmosphericPressure + 0.5 * (pressure[seg.node_a] + pressure[seg.node_b]);
    const WaterState state = water_state(temperature[s], p);
    if (state == WaterState::Liquid) continue;
    long& count = state == WaterState::Boiling ? counters_.boiling : counters_.supercooled;
    ++count;
    if (warning_.empty())
      warning_ = fmt::format(
          "water at {:g} C in {} is {} (absolute pressure {:g} Pa); the viscosity correlation is "
          "for liquid water, its value was used",
          temperature[s], where(g, s),
          state == WaterState::Boiling ? "above its boiling point" : "below freezing", p);
  }
}

nlohmann::json SegmentViscosity::statistics() const {
  nlohmann::json j = {{"correlation", "Kestin, Sokolov & Wakeham 1978 (liquid water, -8 to 150 C)"},
                      {"updates", counters_.updates},
                      {"temperature", {{"min", counters_.lowest}, {"max", counters_.highest}}},
                      {"supercooled_segments", counters_.supercooled},
                      {"boiling_segments", counters_.boiling}};
  if (!warning_.empty()) j["warning"] = warning_;
  return j;
}

}  // namespace fissure::flow
