// Hydraulic apertures from the block system (theory.md 3.1, 6.3 M -> H):
//   e = clip(e0 + u_n + u_dil, e_res, e_max) at each end of every segment,
// where
//  * u_n is the separation of the two walls (wall positions from
//    fracture_walls.h, normal from the left wall towards the right one)
//    where they have moved apart (u_n > 0), and the closure -sigma_n'/k_n of a
//    linear joint law where they are in contact. sigma_n' comes from the
//    contact forces of the mechanics (springs carry the effective stress,
//    theory.md 3.5), spread linearly over the segment with the same resultant
//    and moment. The penalty penetration itself is never used (theory.md 7.3
//    pitfall 7: penalty penetration is not closure);
//  * u_dil = tan(psi) min(|u_s|, u_cs) is shear dilation from the relative
//    tangential wall displacement u_s (optional; psi = 0 switches it off).
// Segments without blocks on both sides keep e0 (clipped).
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "flow/hm/fracture_walls.h"
#include "flow/network/apertures.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct HmApertureLaw {
  double normal_stiffness = 0;  ///< k_n, Pa/m
  double dilation_angle = 0;    ///< psi, rad
  double dilation_limit = 0;    ///< u_cs, m; 0 = no limit
  ApertureLimits limits;
};

/// Per segment end: what the aperture came from (for statistics and tests).
struct WallState {
  std::vector<double> opening_a, opening_b;  ///< wall separation u_n (m), < 0 penetration
  std::vector<double> stress_a, stress_b;  ///< effective normal stress sigma_n' (Pa, compression +)
  std::vector<double> shear_a, shear_b;    ///< relative tangential displacement u_s (m)
  /// de/dp at fixed total stress (m/Pa), for the fluid storage of the
  /// fixed-stress split (docs/flow.md 7): 1/k_n at the ends of segments
  /// between two blocks whose aperture lies strictly between e_res and e_max,
  /// else 0 (a clipped aperture does not move). Where the walls touch under
  /// sigma_n' > 0 this is the joint law's answer to a pressure rise (sigma_n'
  /// falls by dp, the joint opens by dp/k_n); where they are apart it stands
  /// for the contacts that hold the blocks (DDA's penalty springs, stiffer
  /// than k_n in the examples).
  std::vector<double> compliance_a, compliance_b;
};

void hm_apertures(const FractureGraph& graph, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const HmApertureLaw& law,
                  std::vector<double>& aperture_a, std::vector<double>& aperture_b,
                  WallState* wall_state = nullptr);

}  // namespace fissure::flow
