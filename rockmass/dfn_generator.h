// Stochastic discrete fracture networks (docs/rock-mass.md section 3): each
// family is a Poisson process of straight fractures in the plane with
// intensity P20 (centres per unit area) and independent marks: direction,
// length and aperture (which may depend on the length).
//
// Only the fractures that can reach the domain are drawn. A fracture of
// length l reaches the domain's bounding box B (W x H) only if its centre lies
// in B grown by l/2 on every side, so the fractures drawn are those with
// centre in that window: a Poisson process whose number has mean
//   P20 (W H + (W + H) E[l] + E[l^2]),
// whose lengths follow the mixture of p(l), l p(l) / E[l] and l^2 p(l) /
// E[l^2] with weights W H, (W + H) E[l], E[l^2], and whose centres are uniform
// in the window of their length. Restricted to centres inside the domain this
// is exactly the requested process, and the expected trace length per unit
// area inside the domain is exactly P21 = P20 E[l].
#pragma once

#include <vector>

#include "core/geometry/polygon.h"
#include "rockmass/distributions.h"
#include "rockmass/fracture_trace.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

struct DfnFracture {
  Vec2 centre = Vec2::Zero();
  double length = 0;    ///< m
  double angle = 0;     ///< direction in [0, pi), rad
  double aperture = 0;  ///< m

  FractureTrace trace(int set, int joint) const;
};

/// P20 of a family: given, or P21 / E[l].
double dfn_p20(const DfnFamilySpec& spec);

/// Expected number of fractures drawn for `domain` (see above).
double expected_dfn_fractures(const DfnFamilySpec& spec, const Box& domain);

/// One realisation of the family over `domain`.
std::vector<DfnFracture> generate_dfn_family(const DfnFamilySpec& spec, const Box& domain,
                                             Rng& rng);

}  // namespace fissure
