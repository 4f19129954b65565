#include "core/scene/exchanged_field.h"

#include <stdexcept>

namespace fissure {

double default_absolute_tolerance(const QuantityKind& kind) {
  // Far below what a measurement of rock resolves, far above the round-off
  // of the values' usual magnitudes (1e-16 relative).
  struct Default {
    Dimension dimension;
    double tolerance;
  };
  static constexpr Default kDefaults[] = {
      {{}, 1e-12},                // strain, ratio
      {{0, 1, 0, 0, 0}, 1e-12},   // m: aperture, displacement
      {{1, -1, -2, 0, 0}, 1e-3},  // Pa: 0.1 um of water head
      {{0, 0, 0, 1, 0}, 1e-6},    // K
      {{0, 1, -1, 0, 0}, 1e-15},  // m/s: a flux per area
      {{0, 2, -1, 0, 0}, 1e-15},  // m^2/s: a flux per unit thickness
      {{1, 0, -3, 0, 0}, 1e-6},   // W/m^2
      {{1, 0, -2, 0, 0}, 1e-6},   // N/m: a force per unit thickness
      {{1, 1, -3, 0, 0}, 1e-9},   // W/m: a heat flow per unit thickness
  };
  for (const Default& d : kDefaults)
    if (d.dimension == kind.dimension) return d.tolerance;
  throw std::logic_error("no default absolute tolerance for an exchanged " +
                         std::string(kind.name) + " (core/scene/exchanged_field.cpp)");
}

}  // namespace fissure
