// How big a rock mass will be, before anything is generated: the check of
// `max_fractures` and `max_blocks` (docs/rock-mass.md section 5), so that a
// density typed wrong is an error with the estimate, not an out-of-memory
// crash.
//
// Intersections: two independent stationary line processes with intensities
// (length per area) P21_a and P21_b and directions theta_a, theta_b cross
// P21_a P21_b E|sin(theta_a - theta_b)| times per unit area (the
// Buffon/Miles intersection density; Stoyan, Kendall and Mecke, Stochastic
// Geometry, ch. 8); a process with itself crosses half that. The number of
// blocks cannot exceed one plus the number of intersections (each crossing
// closes at most one new face), and equals it for persistent sets, so the
// estimate is 1 + A sum_{a <= b} (intersection density), plus one per
// excavation. Short DFN fractures end inside blocks, so for them it is an
// upper bound on average.
#pragma once

#include "rockmass/rock_mass_spec.h"

namespace fissure {

struct RockMassEstimate {
  double fractures = 0;      ///< traces to be generated
  double intersections = 0;  ///< expected crossings inside the domain
  double blocks = 0;         ///< 1 + intersections + excavations
};

RockMassEstimate estimate_rock_mass(const RockMassSpec& spec);

/// Expected crossings per unit area (1/m^2) of the traces of DFN `families`
/// (the intersection density above): the size of a REV study's networks.
double dfn_crossing_density(const std::vector<DfnFamilySpec>& families);

}  // namespace fissure
