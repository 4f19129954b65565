// Stochastic discrete fracture networks (docs/rock-mass.md section 3): each
// family is a Poisson process of straight fractures in the plane with
// intensity P20 (centres per unit area) and independent marks: direction,
// length and aperture (which may depend on the length).
//
// Only the fractures that can reach the domain are drawn, from one of two
// windows around the domain's bounding box B (W x H); restricted to the
// fractures that meet B, both give exactly the requested process, and the
// expected trace length per unit area inside B is P21 = P20 E[l].
//
// Grown window (fractures short against B). A fracture of length l can meet
// B only if its centre lies in B grown by l/2 on every side, so the
// fractures drawn are those centred in that window: a Poisson process whose
// number has mean
//   P20 (W H + (W + H) E[l] + E[l^2]),
// whose lengths follow the mixture of p(l), l p(l) / E[l] and l^2 p(l) /
// E[l^2] with weights W H, (W + H) E[l], E[l^2], and whose centres are
// uniform in the window of their length (the enlarged generation region of
// DFN practice). Its corners (the E[l^2] term) hold fractures that miss B.
//
// Strip window (long fractures: when those corners would more than double
// the work). A fracture of direction d = (cos t, sin t) meets B exactly when
// its centre lies in the Minkowski sum of B and the fracture, of area
// W H + l (H |cos t| + W sin t) (Santalo 1976, Integral Geometry and
// Geometric Probability, the kinematic measure of segments meeting a convex
// set). That sum splits into three pieces: the fracture's forward end c +
// l d / 2 in B (area W H), or its last exit from B through the side facing
// d, x = const (area l H |cos t|), or through the top (area l W sin t). The
// drawn fractures are a Poisson process with mean number
//   P20 (W H + (W + H) E[l]),
// lengths p(l) for the first piece and l p(l) / E[l] for the others, the
// exit point uniform on its side and at a uniform position along the
// fracture; those of the second and third pieces are kept with probability
// |cos t| and sin t (thinning, Lewis and Shedler 1979, Naval Res. Logist.
// Q. 26:403), so that every kept fracture meets B. The work no longer grows
// with the lengths: for a given P21 it is P20 W H + P21 (W + H).
//
// The grown window is used whenever its corners add at most the rest of its
// work (E[l^2] <= W H + (W + H) E[l]), so families of fractures shorter than
// about the domain draw what they always drew.
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

/// True when the family is drawn in the strip window over `domain` (above).
bool dfn_uses_strips(const DfnFamilySpec& spec, const Box& domain);

/// Expected number of fractures drawn for `domain`, including those the
/// strip window thins out (the work of generate_dfn_family).
double expected_dfn_fractures(const DfnFamilySpec& spec, const Box& domain);

/// One realisation of the family over `domain`.
std::vector<DfnFracture> generate_dfn_family(const DfnFamilySpec& spec, const Box& domain,
                                             Rng& rng);

}  // namespace fissure
