// One explicit DEM cycle over rigid blocks (Cundall and Hart 1992; UDEC's
// cycle; docs/theory.md, "Explicit DEM"), the core the DEM process will
// drive (work in progress, issue 37; one joint law for every contact yet):
//   1. contacts of the current geometry (contact_geometry.h): found anew
//      (each keeping its joint-law state by its key; a new contact starts at
//      its gap, without stress, and without a bond: it was not closed at the
//      start) once some block has moved by a quarter of the margin since the
//      last search, so that no two blocks can have closed a gap of the
//      margin unseen; in between, the known contacts' gaps, normals and
//      points are updated at the new geometry;
//   2. each contact's displacement increment from the velocities of the last
//      half step (contact_kinematics.h), its stresses from the joint law,
//      and the loads on its two blocks, summed in the contacts' order (the
//      same sums on any number of threads);
//   3. each free block's velocities and position (rigid_block_motion.h).
#pragma once

#include <vector>

#include "mechanics/dem/contact_geometry.h"
#include "mechanics/dem/rigid_block_motion.h"
#include "rockmass/joints/coulomb_slip.h"

namespace fissure::dem {

struct DemBlock {
  Polygon polygon;
  Vec2 centroid = Vec2::Zero();
  RigidBody body;
  Motion velocity = Motion::Zero();  ///< at the last half step (x, y, rotation)
  bool fixed = false;
};

struct DemContact {
  ContactGeometry geometry;
  joints::CoulombSlip::State law;
  double normal_stress = 0, shear_stress = 0;  ///< Pa, of the last cycle
};

struct DemSettings {
  double rounding = 0;   ///< m, UDEC's rounding length
  double margin = 0;     ///< m, contacts listed within this gap
  double time_step = 0;  ///< s
  DampingControls damping;
  Vec2 gravity = Vec2::Zero();
};

class DemSystem {
 public:
  DemSystem(std::vector<DemBlock> blocks, const joints::CoulombProperties& joint,
            const DemSettings& settings);

  /// One cycle of time_step.
  void step();

  const std::vector<DemBlock>& blocks() const { return blocks_; }
  const std::vector<DemContact>& contacts() const { return contacts_; }
  double time() const { return time_; }

 private:
  void detect();
  /// The geometry the cycle works on: found anew or updated.
  void locate_contacts();
  std::vector<BlockLoad> contact_loads();

  std::vector<DemBlock> blocks_;
  joints::CoulombSlip law_;
  DemSettings s_;
  std::vector<DemContact> contacts_;
  double time_ = 0;
  bool started_ = false;
  /// Per block: the farthest a point of it can have moved since the last
  /// search (its centroid's move plus its turn times its radius), and its
  /// radius (the farthest vertex from the centroid).
  std::vector<double> moved_, radius_;
  long searches_ = 0;

 public:
  /// Contact searches so far (the others updated the known contacts).
  long searches() const { return searches_; }
};

}  // namespace fissure::dem
