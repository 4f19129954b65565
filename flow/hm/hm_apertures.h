// Hydraulic apertures from the block system (theory.md 3.1, 3.8, 6.3 M -> H):
// at each end of every segment between two blocks, the aperture law of the
// fracture's joint (joint_apertures.h) takes
//  * the separation d of the two walls (wall positions from
//    fracture_walls.h, normal from the left wall towards the right one), of
//    which only an opening (d > 0) is used: where the walls touch the law's
//    closure under sigma_n' takes its place. sigma_n' comes from the contact
//    forces of the mechanics (springs carry the effective stress, theory.md
//    3.5), spread linearly over the segment with the same resultant and
//    moment. The penalty penetration itself is never used (theory.md 7.3
//    pitfall 7: penalty penetration is not closure);
//  * the relative tangential wall displacement u_s, for the dilation.
// With flow.hm's law (joints without a model):
//   e = clip(e0 + u_n + tan(psi) min(|u_s|, u_cs), e_res, e_max),
//   u_n = d where d > 0, -sigma_n'/k_n where the walls touch.
// Segments without blocks on both sides keep e0 (clipped).
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/joint_apertures.h"
#include "flow/network/apertures.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

/// Per segment end: what the aperture came from (for statistics and tests).
struct WallState {
  std::vector<double> opening_a, opening_b;  ///< wall separation u_n (m), < 0 penetration
  std::vector<double> stress_a, stress_b;  ///< effective normal stress sigma_n' (Pa, compression +)
  std::vector<double> shear_a, shear_b;    ///< relative tangential displacement u_s (m)
  /// de/dp at fixed total stress (m/Pa), for the fluid storage of the
  /// fixed-stress split (docs/flow.md 7): de/du_n / k_n (1/k_n with flow.hm's
  /// law; k_n the joint law's tangent at sigma_n') at the ends of segments
  /// between two blocks whose aperture lies strictly between e_res and e_max,
  /// else 0 (a clipped aperture does not move). Where the walls touch under
  /// sigma_n' > 0 this is the joint law's answer to a pressure rise (sigma_n'
  /// falls by dp, the joint opens by dp/k_n); where they are apart it stands
  /// for the contacts that hold the blocks (DDA's penalty springs, stiffer
  /// than k_n in the examples).
  std::vector<double> compliance_a, compliance_b;
};

/// `reference_closure` (per segment, m; empty: none): the closure its
/// walls already carry in the geometry the network was cut from (contacts
/// prestressed by an initial stress touch there without overlapping), so
/// that a wall separation d is an opening only beyond it: d - closure.
void hm_apertures(const FractureGraph& graph, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const FractureApertureLaws& laws,
                  std::vector<double>& aperture_a, std::vector<double>& aperture_b,
                  WallState* wall_state = nullptr,
                  const std::vector<double>& reference_closure = {});
/// Every segment with flow.hm's law.
void hm_apertures(const FractureGraph& graph, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const HmApertureLaw& law,
                  std::vector<double>& aperture_a, std::vector<double>& aperture_b,
                  WallState* wall_state = nullptr);

}  // namespace fissure::flow
