// Hydraulic apertures and cubic-law conductances (theory.md 3.1, 3.2).
//
// A segment carries q = c (p*_a - p*_b) (m^2/s per unit thickness) with
//   c = e_h^3 / (12 mu L),
// where e_h is the segment's hydraulic aperture: its aperture when both ends
// have the same aperture, and Iwai's wedge aperture otherwise,
//   e_h^3 = 2 e_a^2 e_b^2 / (e_a + e_b)   (Jing eqs. 14-15),
// which is exact for an aperture varying linearly from e_a to e_b under the
// cubic law (integrate dp/ds = -12 mu q / e(s)^3 along the segment).
#pragma once

namespace fissure::flow {

/// Bounds on the hydraulic aperture e = e0 + u_n (theory.md 3.1): the residual
/// aperture keeps closed joints conductive (the network stays connected), the
/// maximum stops runaway opening.
struct ApertureLimits {
  double residual = 0;  ///< e_res, m (> 0 in scenes; 0 disables the lower clip)
  double maximum = 0;   ///< e_max, m; 0 = no upper clip
};

/// e clipped to [residual, maximum].
double clip_aperture(double e, const ApertureLimits& limits);

/// Iwai's hydraulic aperture of a linear wedge from e_a to e_b (both > 0).
double iwai_aperture(double e_a, double e_b);

/// Cubic-law conductance e_h^3 / (12 mu L) of a segment with end apertures
/// e_a, e_b (m), length (m) and viscosity (Pa s). Units: m^2 / (Pa s).
double segment_conductance(double e_a, double e_b, double length, double viscosity);

}  // namespace fissure::flow
