// The aperture law of a fracture between two blocks (theory.md 3.8,
// docs/joints.md section 6): how a segment end's wall separation d, its
// effective normal stress sigma_n' and its shear u_s give the hydraulic
// aperture, following the joint of the fracture (the joint of its walls'
// block edges, blocks[].edge_joint, as the mechanics' contacts use it):
//  * a joint without a model: flow.hm's linear law,
//      e = e0 + u_n + tan(psi) min(|u_s|, u_cs),  u_n = d (d > 0), -sigma_n'/k_n (touching);
//  * coulomb: the same with the joint's k_n and its psi and u_cs where it
//    gives them (k_n > 0, psi > 0), flow.hm's where it does not;
//  * continuously_yielding: u_n = -c(sigma_n') on its normal curve where the
//    walls touch; flow.hm's dilation (the law's follows its plastic slip,
//    which no shared field carries);
//  * barton_bandis: the mechanical aperture E = E_0 + u_n + u_dil with
//    u_n = -dV(sigma_n') on Bandis's hyperbola where the walls touch and
//    u_dil the law's mobilized dilation after |u_s| at sigma_n' (Barton,
//    Bandis and Bakhtar 1985), and the hydraulic aperture
//    e = E^2 / JRC_0^2.5 (micrometres), at most E; the fracture's e0 is not
//    used (E_0 and JRC_0 give it).
// Then e is clipped to [e_res, e_max]. The compliance de/dp at fixed total
// stress (the fixed-stress storage, docs/flow.md 7) is de/du_n / k_n at
// sigma_n' (k_n the law's tangent), 0 where e is clipped.
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "flow/network/apertures.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/joints/barton_bandis.h"
#include "rockmass/joints/continuously_yielding.h"

namespace fissure::flow {

/// flow.hm's aperture law: that of the fractures whose joint has no model.
struct HmApertureLaw {
  double normal_stiffness = 0;  ///< k_n, Pa/m
  double dilation_angle = 0;    ///< psi, rad
  double dilation_limit = 0;    ///< u_cs, m; 0 = no limit
  ApertureLimits limits;
};

/// A segment end as the walls and the contacts give it.
struct WallEnd {
  double opening = 0;  ///< d: the walls' normal separation, m (< 0: penetration)
  double stress = 0;   ///< sigma_n', Pa, compression +
  double shear = 0;    ///< u_s: the walls' relative tangential displacement, m
};

/// Its hydraulic aperture (m) and de/dp at fixed total stress (m/Pa).
struct EndAperture {
  double aperture = 0;
  double compliance = 0;
};

class FractureApertureLaw {
 public:
  /// flow.hm's law.
  explicit FractureApertureLaw(const HmApertureLaw& hm);
  /// The law of `joint`: its model's where it has one, flow.hm's for what
  /// the model does not give.
  FractureApertureLaw(const JointProperties& joint, const HmApertureLaw& hm);

  /// At an end of a fracture segment of aperture e0 at zero normal
  /// displacement (m) and length `length` (m: Barton-Bandis's field length
  /// when its joint gives none).
  EndAperture at(const WallEnd& end, double e0, double length) const;
  /// The joint's normal closure (m) under sigma_n' (Pa, compression +).
  double closure(double normal_stress, double length) const;
  /// A segment without blocks on both sides, whatever its joint: e0, clipped.
  double unloaded(double e0) const { return clip_aperture(e0, limits_); }

 private:
  struct Linear {
    double normal_stiffness = 0, tan_psi = 0, dilation_limit = 0;
  };
  struct Yielding {
    joints::ContinuouslyYielding law;
    double tan_psi = 0, dilation_limit = 0;
  };
  struct Bandis {
    joints::BartonBandis law;
  };
  std::variant<Linear, Yielding, Bandis> law_;
  ApertureLimits limits_;
};

/// The aperture law of every segment of a network.
class FractureApertureLaws {
 public:
  /// flow.hm's law for every segment.
  explicit FractureApertureLaws(const HmApertureLaw& hm);
  /// One law per scene joint (flow.hm's for the joints without a model);
  /// flow.hm's for every segment until assign().
  FractureApertureLaws(const std::vector<JointProperties>& joints, const HmApertureLaw& hm);

  /// Each segment between two blocks takes the joint of its walls' block
  /// edges (blocks[].edge_joint); where the two walls have different joints,
  /// the one with a model. Two different joints with models on the walls of
  /// one fracture are a SceneError (`where` says where the scene sets the
  /// network up).
  void assign(const FractureGraph& graph, const std::vector<Block>& blocks,
              const std::vector<JointProperties>& joints, const std::string& where);

  /// The law of scene joint `joint` (flow.hm's for a joint without a model).
  const FractureApertureLaw& of_joint(int joint) const {
    return laws_[law_of_joint_.empty() ? 0 : law_of_joint_[joint]];
  }
  const FractureApertureLaw& of_segment(int segment) const {
    return laws_[law_of_.empty() ? 0 : law_of_[segment]];
  }
  /// Whether some segment follows a joint model.
  bool any_model() const { return any_model_; }
  /// The number of segments per law: "flow.hm", or the joint's name.
  std::map<std::string, int> segments_per_law() const;

 private:
  std::vector<FractureApertureLaw> laws_;  ///< [0]: flow.hm's; then per scene joint
  std::vector<std::string> names_;         ///< of laws_: "flow.hm", then the joints' names
  std::vector<int> law_of_joint_;          ///< per scene joint: index into laws_
  std::vector<int> law_of_;                ///< per segment: index into laws_ (empty: 0)
  bool any_model_ = false;
};

}  // namespace fissure::flow
