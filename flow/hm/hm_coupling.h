// The flow's coupling with the block mechanics (theory.md 3.1, 3.5, 6.3),
// switched on by the scene's flow.hm section: the walls of every fracture
// segment move with the blocks on its sides, the hydraulic apertures follow
// from the walls and the contacts of the mechanics by the aperture law of
// each fracture's joint (hm_apertures.h, joint_apertures.h; M -> H), and the pressures load the
// blocks' edges (pressure_loads.h; H -> M). What crosses over goes through the shared fields
// "contacts" and "pressure_loads"; the flow never calls the mechanics.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"

namespace fissure::flow {

class HmCoupling {
 public:
  /// flow.hm's law for the fractures whose joint (of `joints`, the scene's)
  /// has no model, the joint's for the others.
  HmCoupling(const HmApertureLaw& law, const std::vector<JointProperties>& joints)
      : laws_(joints, law) {}

  /// Each segment's joint, from the blocks its walls belong to (after the
  /// network is built; FractureApertureLaws::assign).
  void assign_joints(const FractureGraph& graph, const RockMass& state, const std::string& where) {
    laws_.assign(graph, state.blocks, state.joints, where);
  }
  const FractureApertureLaws& laws() const { return laws_; }

  /// The walls of every segment where the blocks have moved them from
  /// `blocks` (the geometry the network's `nodes` lie in), and the apertures
  /// at both ends from them and the state's contacts.
  void apertures(const FractureGraph& graph, const std::vector<Vec2>& nodes,
                 const BlockReference& blocks, const RockMass& state,
                 std::vector<SegmentWalls>& walls, std::vector<double>& aperture_a,
                 std::vector<double>& aperture_b);

  /// The node pressures as loads on the block walls (the shared field
  /// "pressure_loads"), for the mechanics' next steps.
  void load_blocks(const FractureGraph& graph, const std::vector<SegmentWalls>& walls,
                   const std::vector<double>& pressure, RockMass& state) const;

  /// What the last apertures came from (hm_apertures.h).
  const WallState& wall_state() const { return wall_state_; }

 private:
  FractureApertureLaws laws_;
  WallState wall_state_;
};

}  // namespace fissure::flow
