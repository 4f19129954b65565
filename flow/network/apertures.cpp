#include "flow/network/apertures.h"

#include <algorithm>
#include <cmath>

namespace fissure::flow {

double clip_aperture(double e, const ApertureLimits& limits) {
  if (limits.maximum > 0) e = std::min(e, limits.maximum);
  return std::max(e, limits.residual);
}

double iwai_aperture(double e_a, double e_b) {
  if (e_a == e_b) return e_a;
  // e^3 = 2 e_a^2 e_b^2 / (e_a + e_b); written as a product so that tiny
  // apertures (1e-6 m: e^4 ~ 1e-24) do not lose digits.
  return std::cbrt(2 * (e_a * e_b) * (e_a * e_b) / (e_a + e_b));
}

double segment_conductance(double e_a, double e_b, double length, double viscosity) {
  const double e3 = e_a == e_b ? e_a * e_a * e_a : 2 * (e_a * e_b) * (e_a * e_b) / (e_a + e_b);
  return e3 / (12 * viscosity * length);
}

}  // namespace fissure::flow
