#include "flow/hm/joint_apertures.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "rockmass/joints/joint_model.h"

namespace fissure::flow {

namespace {

/// Walls closer than this fraction of the segment's length touch.
constexpr double kTouching = 1e-12;

/// The shear that dilates: |u_s|, at most u_cs (0: no limit).
double dilating_shear(double shear, double limit) {
  return limit > 0 ? std::min(std::abs(shear), limit) : std::abs(shear);
}

bool clipped(double e, const ApertureLimits& limits) {
  return e <= limits.residual || (limits.maximum > 0 && e >= limits.maximum);
}

const joints::JointModel* model_of(const JointProperties& joint) {
  return joint.model.find(joints::kJointModel);
}

}  // namespace

FractureApertureLaw::FractureApertureLaw(const HmApertureLaw& hm)
    : law_(Linear{hm.normal_stiffness, std::tan(hm.dilation_angle), hm.dilation_limit}),
      limits_(hm.limits) {}

FractureApertureLaw::FractureApertureLaw(const JointProperties& joint, const HmApertureLaw& hm)
    : FractureApertureLaw(hm) {
  const joints::JointModel* model = model_of(joint);
  if (!model) return;
  const double hm_tan_psi = std::tan(hm.dilation_angle);
  switch (joints::kind_of(*model)) {
    case joints::JointModelKind::Coulomb: {
      const auto& c = std::get<joints::CoulombProperties>(*model);
      const bool dilates = c.dilation_angle > 0;
      law_ = Linear{c.normal_stiffness > 0 ? c.normal_stiffness : hm.normal_stiffness,
                    dilates ? std::tan(c.dilation_angle) : hm_tan_psi,
                    dilates ? c.zero_dilation_displacement : hm.dilation_limit};
      break;
    }
    case joints::JointModelKind::ContinuouslyYielding:
      law_ = Yielding{
          joints::ContinuouslyYielding(std::get<joints::ContinuouslyYieldingProperties>(*model)),
          hm_tan_psi, hm.dilation_limit};
      break;
    case joints::JointModelKind::BartonBandis:
      law_ = Bandis{joints::BartonBandis(std::get<joints::BartonBandisProperties>(*model))};
      break;
  }
}

EndAperture FractureApertureLaw::at(const WallEnd& end, double e0, double length) const {
  EndAperture r;
  // Walls apart by less than round-off of the length (1e-12 m for 1 m,
  // walls that have not moved) touch: where they carry a stress, the
  // joint's closure under it counts.
  const double opening = end.opening > kTouching * length ? end.opening : 0;
  if (const auto* l = std::get_if<Linear>(&law_)) {
    // Written as before the joint models, to the bit.
    const double un = opening > 0 ? opening : -end.stress / l->normal_stiffness;
    r.aperture =
        clip_aperture(e0 + un + l->tan_psi * dilating_shear(end.shear, l->dilation_limit), limits_);
    r.compliance = clipped(r.aperture, limits_) ? 0 : 1 / l->normal_stiffness;
  } else if (const auto* y = std::get_if<Yielding>(&law_)) {
    const double un = opening > 0 ? opening : -y->law.closure(end.stress);
    r.aperture =
        clip_aperture(e0 + un + y->tan_psi * dilating_shear(end.shear, y->dilation_limit), limits_);
    r.compliance = clipped(r.aperture, limits_) ? 0 : 1 / y->law.normal_stiffness(end.stress);
  } else {
    const joints::BartonBandis& law = std::get<Bandis>(law_).law;
    const joints::BartonBandis::Loaded joint =
        law.loaded(end.stress, end.shear, law.field_length(length));
    const double un = opening > 0 ? opening : -joint.closure;
    const double mechanical =
        std::max(0.0, law.properties().initial_aperture + un + joint.dilation);
    const double hydraulic = joints::hydraulic_aperture(mechanical, law.properties().jrc);
    r.aperture = clip_aperture(hydraulic, limits_);
    // e = E^2 / c below the cap: de/dE = 2 e / E; at the cap de/dE = 1.
    const double slope = hydraulic < mechanical ? 2 * hydraulic / mechanical : 1;
    r.compliance =
        clipped(r.aperture, limits_) || mechanical <= 0 ? 0 : slope / joint.normal_stiffness;
  }
  return r;
}

double FractureApertureLaw::closure(double normal_stress, double length) const {
  if (!(normal_stress > 0)) return 0;
  if (const auto* l = std::get_if<Linear>(&law_)) return normal_stress / l->normal_stiffness;
  if (const auto* y = std::get_if<Yielding>(&law_)) return y->law.closure(normal_stress);
  const joints::BartonBandis& law = std::get<Bandis>(law_).law;
  return law.loaded(normal_stress, 0, law.field_length(length)).closure;
}

FractureApertureLaws::FractureApertureLaws(const HmApertureLaw& hm)
    : laws_{FractureApertureLaw(hm)}, names_{"flow.hm"} {}

FractureApertureLaws::FractureApertureLaws(const std::vector<JointProperties>& joints,
                                           const HmApertureLaw& hm)
    : FractureApertureLaws(hm) {
  law_of_joint_.assign(joints.size(), 0);
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (model_of(joints[j])) {
      law_of_joint_[j] = static_cast<int>(laws_.size());
      laws_.emplace_back(joints[j], hm);
      names_.push_back(joints[j].name);
    }
}

void FractureApertureLaws::assign(const FractureGraph& g, const std::vector<Block>& blocks,
                                  const std::vector<JointProperties>& joints,
                                  const std::string& where) {
  // The joint of a wall: its block edge's (-1: none known).
  auto joint_of = [&](const BlockFace& f) {
    if (f.block < 0 || f.edge < 0) return -1;
    const std::vector<int>& edge_joint = blocks[f.block].edge_joint;
    return f.edge < static_cast<int>(edge_joint.size()) ? edge_joint[f.edge] : -1;
  };
  auto law_of_joint = [&](int joint) {
    return joint >= 0 && joint < static_cast<int>(law_of_joint_.size()) ? law_of_joint_[joint] : 0;
  };
  law_of_.assign(g.n_segments(), 0);
  any_model_ = false;
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    const int left = joint_of(seg.left), right = joint_of(seg.right);
    const int law_left = law_of_joint(left), law_right = law_of_joint(right);
    if (law_left > 0 && law_right > 0 && law_left != law_right) {
      const Vec2& a = g.nodes[seg.node_a];
      const Vec2& b = g.nodes[seg.node_b];
      // Named in the order of the blocks.
      const bool left_first = seg.left.block < seg.right.block;
      const BlockFace& first = left_first ? seg.left : seg.right;
      const BlockFace& second = left_first ? seg.right : seg.left;
      FISSURE_CHECK(false, SceneError,
                    where << ": the fracture from (" << a.x() << ", " << a.y() << ") to (" << b.x()
                          << ", " << b.y() << ") lies between block '" << blocks[first.block].name
                          << "' with joint '" << joints[joint_of(first)].name << "' and block '"
                          << blocks[second.block].name << "' with joint '"
                          << joints[joint_of(second)].name
                          << "', two joints with a model each; expected one joint law for the "
                             "flow's aperture (the same joint on both blocks, or a joint "
                             "without a model on one of them)");
    }
    law_of_[s] = std::max(law_left, law_right);
    any_model_ = any_model_ || law_of_[s] > 0;
  }
}

std::map<std::string, int> FractureApertureLaws::segments_per_law() const {
  std::map<std::string, int> counts;
  for (const int law : law_of_) ++counts[names_[law]];
  return counts;
}

}  // namespace fissure::flow
