// One explicit DEM cycle over rigid and deformable (zoned) blocks (Cundall
// and Hart 1992; UDEC's cycle; docs/dem.md sections 2 and 9), the core the
// DEM process drives:
//   0. each zoned block's polygon is its boundary at the nodes' positions,
//      every node a contact point (contact_geometry.h);
//   1. contacts of the current geometry (contact_geometry.h): found anew
//      (each keeping its joint-law state by its key; a new contact starts at
//      its gap, without stress, bonded only when its walls touched at the
//      start of the run) once some block has moved by a quarter of the
//      margin since the last search, so that no two blocks can have closed
//      a gap of the margin unseen; in between, the known contacts' gaps,
//      normals and points are updated at the new geometry;
//   2. each contact's displacement increment from the velocities of the last
//      half step (contact_kinematics.h), its stresses from its joint's law
//      (rockmass/joints/joint_law.h), and the loads on its two blocks: every
//      contact on its own (on all threads), then summed per block in the
//      contacts' order (the same sums, to the bit, on any number of threads);
//   3. each free block's velocities and position (rigid_block_motion.h);
//      a zoned block's zones take their stresses from the last half step's
//      velocities, and its nodes move under the zones', the contacts' (at
//      the node; on an edge, shared by its two nodes as the contact point
//      divides it) and the external forces (zoned_block.h); then the
//      unbalanced-force ratio of the cycle.
#pragma once

#include <optional>
#include <vector>

#include "mechanics/dem/contact_geometry.h"
#include "mechanics/dem/dem_energy.h"
#include "mechanics/dem/rigid_block_motion.h"
#include "mechanics/dem/zoned_block.h"
#include "rockmass/joints/joint_law.h"

namespace fissure::dem {

struct DemBlock {
  Polygon polygon;
  Vec2 centroid = Vec2::Zero();
  RigidBody body;
  Motion velocity = Motion::Zero();  ///< at the last half step (x, y, rotation)
  bool fixed = false;
  /// The joint (index of the system's laws) of each edge v -> next(v); empty: joint 0.
  std::vector<int> edge_joint;
  /// The rock mass's stress at the start (sxx, syy, sxy, Pa, tension +):
  /// the contacts bonded at the start carry it (prestressed).
  Eigen::Vector3d initial_stress = Eigen::Vector3d::Zero();
  /// A deformable block's zones and nodes (empty: rigid). The system then
  /// keeps `polygon` at the boundary nodes (loop after loop, as
  /// ZonedBlock::boundary), `centroid` at the nodes' centre of mass and
  /// `velocity` at their mean motion; `edge_joint` stays per edge of the
  /// block's own polygon (between its corner nodes); `fixed` is for rigid
  /// blocks only.
  std::optional<ZonedBlock> zoned;
};

struct DemContact {
  ContactGeometry geometry;
  int joint = 0;  ///< index of the system's laws
  joints::JointLaw::State law;
  joints::JointResponse response;  ///< of the last cycle (stresses, slip, open)
  /// The stiffness-proportional dashpots' stresses of the last cycle (Pa,
  /// normal compression +): not the joint's, not kept in its state.
  double dashpot_normal = 0, dashpot_shear = 0;
};

struct DemSettings {
  double rounding = 0;   ///< m, UDEC's rounding length
  double margin = 0;     ///< m, contacts listed within this gap
  double time_step = 0;  ///< s
  DampingControls damping;
  /// beta (s): Rayleigh's stiffness-proportional damping, a dashpot beta k
  /// beside each closed contact's springs (the shear one only while it
  /// sticks) and beta times the zones' elastic stress rate in their forces.
  double stiffness_damping = 0;
  Vec2 gravity = Vec2::Zero();
};

/// A quadrature point of a block edge tied to a continuum
/// (rockmass/fields/interface_ties.h) as the cycles apply it: the force
/// force + stiffness (target - x) at the point's present position x, on a
/// rigid block the point at t of its polygon's edge (a, b), on a zoned block
/// the point at t between its boundary nodes a and b.
struct DemTie {
  int block = -1;
  int a = -1, b = -1;
  double t = 0;
  Vec2 force = Vec2::Zero();   ///< N/m
  Vec2 target = Vec2::Zero();  ///< m
  double stiffness = 0;        ///< N/m per m
};

class DemSystem {
 public:
  /// `laws`: one per joint that the blocks' edge_joint name.
  DemSystem(std::vector<DemBlock> blocks, std::vector<joints::JointLaw> laws,
            const DemSettings& settings);

  /// Loads on the rigid blocks besides the contacts' and gravity (point
  /// loads, fluid pressure), held over the next cycles; empty: none.
  void set_external_loads(std::vector<BlockLoad> loads) { external_ = std::move(loads); }
  /// The same on the zoned blocks' nodes (per block, per node; N/m), held
  /// over the next cycles; empty: none.
  void set_nodal_loads(std::vector<std::vector<Vec2>> loads) { nodal_ = std::move(loads); }
  /// Ties to a continuum, their forces taken anew every cycle at the
  /// blocks' present positions; empty: none.
  void set_ties(std::vector<DemTie> ties) { ties_ = std::move(ties); }
  /// A tie's point at the blocks' present positions.
  Vec2 tie_position(const DemTie& tie) const;
  /// Every block at rest (a solved quasi-static state).
  void stop();
  void set_time_step(double dt) { s_.time_step = dt; }
  void set_damping(const DampingControls& damping) { s_.damping = damping; }
  void set_stiffness_damping(double beta) { s_.stiffness_damping = beta; }

  /// The contacts of the current geometry, before the first cycle (for the
  /// other processes to see at the start).
  void prepare();

  /// One cycle of time_step.
  void step();

  /// Scales block b about its centroid by `factor` (a uniform strain: the
  /// heat's free expansion of a rigid block), its inertia with it; the
  /// contacts' laws see the walls' move at their next step.
  void scale_block(int b, double factor);

  /// The largest critical time step (s) of the blocks on their contacts'
  /// current stiffness (sum of k L over each block's contacts, normal and
  /// shear, and the rotational stiffness about its centroid): 2 sqrt(m/k);
  /// of a zoned block, 2 / sqrt(omega_z^2 + omega_c^2), omega_z of its
  /// zones and omega_c^2 the largest k L / m of its nodes' contacts (the
  /// highest frequency of a sum of stiffnesses is at most the root of the
  /// sum of the squares: Weyl's inequality). With stiffness-proportional
  /// damping beta, the damped bound (2 / omega) (sqrt(1 + xi^2) - xi) at
  /// omega = 2 / dt_undamped and xi = beta omega / 2 (Belytschko and Hughes
  /// 1983, central differences with viscous damping).
  double critical_time_step() const;
  /// Whether a joint's stiffness depends on its stress (not Coulomb's).
  bool stiffness_varies() const;

  /// Density scaling, for quasi-static solves in pseudo-time (UDEC's mass
  /// scaling; docs/dem.md section 2): each free block's inertia (a zoned
  /// block's nodal masses, by one factor per block) is raised so that its
  /// critical step on its contacts' current stiffness is the largest
  /// natural one of any block, T, which is returned (infinite: no contact
  /// yet, nothing scaled). Weights stay the blocks' own, so the solved
  /// equilibrium is the same; only the way to it is faster where blocks
  /// differ in size or stiffness.
  double scale_densities();
  /// The largest factor by which scale_densities raised a mass (1: none).
  double largest_mass_scale() const { return largest_mass_scale_; }

  /// Of the last cycle: the largest unbalanced force of a free block over
  /// the mean magnitude of the forces that act on a free block (UDEC's
  /// ratio; 0 at equilibrium, 1 in free fall).
  double unbalanced_force_ratio() const { return ratio_; }

  std::vector<DemBlock>& blocks() { return blocks_; }
  const std::vector<DemBlock>& blocks() const { return blocks_; }
  const std::vector<DemContact>& contacts() const { return contacts_; }
  const std::vector<joints::JointLaw>& laws() const { return laws_; }
  double time() const { return time_; }
  /// Contact searches so far (the other cycles updated the known contacts).
  long searches() const { return searches_; }
  long cycles() const { return cycles_; }
  /// The energy ledger at the last cycle's time (dem_energy.h).
  DemEnergy energy() const;

  /// Everything the next cycles depend on besides the blocks' polygons and
  /// velocities (the process's checkpoint, core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);

 private:
  void detect();
  /// The geometry the cycle works on: found anew or updated.
  void locate_contacts();
  /// The contacts' stresses (when `advance_laws`) and their loads on the
  /// rigid blocks; those on zoned blocks go to their nodes (add_force).
  std::vector<BlockLoad> contact_loads(bool advance_laws);
  /// The velocity of block b's wall at a contact: a rigid block's point, a
  /// zoned block's corner node (side i, or j's corner of a corner-corner
  /// contact) or its edge's nodes interpolated at `weight` (side j).
  Vec2 wall_velocity(int b, const ContactGeometry& g, bool side_i, double weight) const;
  /// Side j of a corner-edge contact on a zoned block: the share of the far
  /// node of the edge (0 at its first node, 1 at its second).
  double edge_weight(const ContactGeometry& g) const;
  /// Block b's zones and nodes (null: a rigid block).
  ZonedBlock* zoned_of(int b) { return blocks_[b].zoned ? &*blocks_[b].zoned : nullptr; }
  /// The node of vertex v of a zoned block's polygon.
  int node_of(int b, int v) const { return boundary_nodes_[b][v]; }
  /// The zoned blocks' boundary nodes, edge joints and polygons (at the
  /// start and after a checkpoint is read).
  void index_zoned_blocks();
  /// Each zoned block's polygon, centroid and mean motion at its nodes'
  /// current positions and velocities.
  void follow_zoned_nodes();
  /// Zoned blocks: stresses, forces and the nodes' motion.
  void move_zoned_blocks();
  /// The stiffness each free block's motion meets: per rigid block k and
  /// k_rot (N/m per m, N m per rad per m) of its contacts; per zoned block
  /// the largest k L / m over its nodes' contacts (1/s^2).
  struct BlockStiffness {
    double k = 0, k_rot = 0, node_omega2 = 0;
  };
  std::vector<BlockStiffness> block_stiffnesses() const;
  /// A free block's critical step at its stiffness, with its own inertia.
  double block_critical_step(std::size_t b, const BlockStiffness& s) const;
  int joint_of(const ContactKey& key) const;
  /// The blocks' polygons where they are (contact_geometry.h).
  const std::vector<const Polygon*>& polygon_refs();
  /// A contact bonded at the start carries the blocks' initial stress.
  void prestress(DemContact& c) const;
  /// The stiffness-proportional dashpots' stresses of a contact after its
  /// law's step over du.
  void update_dashpots(DemContact& c, const DisplacementIncrement& du) const;
  /// The contacts' stored energy now (J/m).
  double contacts_elastic_energy() const;

  std::vector<DemBlock> blocks_;
  std::vector<joints::JointLaw> laws_;
  DemSettings s_;
  std::vector<BlockLoad> external_;
  std::vector<std::vector<Vec2>> nodal_;
  std::vector<DemTie> ties_;
  /// The ties' forces of this cycle on the rigid blocks (added to their
  /// applied loads).
  void add_tie_loads(std::vector<BlockLoad>& applied) const;
  std::vector<DemContact> contacts_;
  /// Per block: for a zoned one, the node and the joint of each vertex of
  /// its polygon (of the edge from it); and whether every vertex is a
  /// contact point (find_contacts).
  std::vector<std::vector<int>> boundary_nodes_, boundary_joints_;
  std::vector<std::uint8_t> every_vertex_;
  bool any_zoned_ = false;
  /// Per contact, of the cycle: side j's edge weight on a zoned block.
  std::vector<double> edge_weight_;
  /// Per contact, of the cycle: the loads on its blocks i and j.
  std::vector<BlockLoad> on_i_, on_j_;
  /// Scratch of the contacts' update, kept for its storage.
  std::vector<const Polygon*> polygon_refs_;
  std::vector<std::vector<RoundedCorner>> corners_;
  double time_ = 0, ratio_ = 0;
  /// The step of the last motion: the contacts' increments are the last
  /// half step's velocities times it (the step may change between cycles).
  double last_step_ = 0;
  bool started_ = false;
  /// Per block: the farthest a point of it can have moved since the last
  /// search (its centroid's move plus its turn times its radius), and its
  /// radius (the farthest vertex from the centroid).
  std::vector<double> moved_, radius_;
  /// Per block: its expansion e (scale factor - 1) since the laws' last
  /// step, which the next one adds to the contacts' increments.
  std::vector<double> expansion_;
  bool expanded_ = false;
  /// Density scaling's inertia of the rigid blocks (empty: their own).
  std::vector<RigidBody> inertial_;
  /// Per block: the factor of its largest raised inertia (1: none).
  std::vector<double> mass_scale_;
  double largest_mass_scale_ = 1;
  long searches_ = 0, cycles_ = 0;

  // The energy ledger (dem_energy.h). Per contact, of the cycle: the work
  // on its springs, on its dashpots and the heat's expansion's share.
  std::vector<double> spring_work_, dashpot_work_, expansion_work_;
  /// Per rigid block, of the cycle.
  std::vector<RigidStepEnergy> block_energy_;
  double kinetic_ = 0;  ///< the rigid blocks', at the last cycle's time
  CycleSum gravity_work_, applied_work_;
  CycleSum damping_dissipated_{CycleSum::FirstShare::Whole};
  /// Sums over the contacts since the start (J/m), and their stored energy
  /// at the start.
  double contact_work_ = 0, dashpot_dissipated_ = 0, expansion_work_sum_ = 0;
  double stored_at_start_ = 0;
};

template <class Self, class Archive>
void DemSystem::checkpoint(Self& self, Archive& a) {
  a("time", self.time_);
  a("ratio", self.ratio_);
  a("last_step", self.last_step_);
  a("started", self.started_);
  a("moved", self.moved_);
  a("radius", self.radius_);
  a("expansion", self.expansion_);
  a("expanded", self.expanded_);
  a("searches", self.searches_);
  a("cycles", self.cycles_);
  // The energy ledger (absent from checkpoints of before it: started anew).
  bool ledger = true;
  if constexpr (Archive::reading) ledger = a.has("kinetic");
  if (ledger) {
    a("kinetic", self.kinetic_);
    CycleSum::checkpoint(self.gravity_work_, a, "gravity_work");
    CycleSum::checkpoint(self.applied_work_, a, "applied_work");
    CycleSum::checkpoint(self.damping_dissipated_, a, "damping_dissipated");
    a("contact_work", self.contact_work_);
    a("dashpot_dissipated", self.dashpot_dissipated_);
    a("expansion_work", self.expansion_work_sum_);
    a("stored_at_start", self.stored_at_start_);
  }
  // The blocks' own centroids and inertia (moved and scaled since the start:
  // not those of the restored polygons, which differ in the last bits).
  std::vector<Vec2> centroids;
  std::vector<double> masses, inertias;
  if constexpr (!Archive::reading)
    for (const DemBlock& b : self.blocks_) {
      centroids.push_back(b.centroid);
      masses.push_back(b.body.mass);
      inertias.push_back(b.body.inertia);
    }
  a("centroids", centroids);
  a("masses", masses);
  a("inertias", inertias);
  a.list("contacts", self.contacts_, [](auto& e, auto& c) {
    e("block_i", c.geometry.key.block_i);
    e("corner", c.geometry.key.corner);
    e("block_j", c.geometry.key.block_j);
    e("feature", c.geometry.key.feature);
    e("point", c.geometry.point);
    e("normal", c.geometry.normal);
    e("gap", c.geometry.gap);
    e("length", c.geometry.length);
    e("joint", c.joint);
    e("normal_stress", c.response.normal_stress);
    e("shear_stress", c.response.shear_stress);
    e("slipping", c.response.slipping);
    e("open", c.response.open);
  });
  std::vector<Eigen::Vector2d> dashpots;
  if constexpr (!Archive::reading)
    for (const DemContact& c : self.contacts_)
      dashpots.emplace_back(c.dashpot_normal, c.dashpot_shear);
  bool with_dashpots = true;
  if constexpr (Archive::reading) with_dashpots = a.has("dashpots");
  if (with_dashpots) a("dashpots", dashpots);
  for (std::size_t b = 0; b < self.blocks_.size(); ++b)
    if (self.blocks_[b].zoned) {
      auto zoned = a.section("zoned_block_" + std::to_string(b));
      ZonedBlock::checkpoint(*self.blocks_[b].zoned, zoned);
    }
  std::vector<joints::JointLaw::State> states;
  if constexpr (!Archive::reading)
    for (const DemContact& c : self.contacts_) states.push_back(c.law);
  joints::checkpoint_law_states(a, states);
  if constexpr (Archive::reading) {
    const std::size_t n = self.blocks_.size();
    FISSURE_CHECK(centroids.size() == n && masses.size() == n && inertias.size() == n &&
                      self.moved_.size() == n && self.radius_.size() == n &&
                      self.expansion_.size() == n && states.size() == self.contacts_.size(),
                  IoError, "checkpoint: the DEM's blocks or contacts do not match the scene's");
    for (std::size_t b = 0; b < n; ++b) {
      self.blocks_[b].centroid = centroids[b];
      self.blocks_[b].body = {masses[b], inertias[b]};
    }
    for (std::size_t k = 0; k < states.size(); ++k) self.contacts_[k].law = states[k];
    FISSURE_CHECK(dashpots.empty() || dashpots.size() == self.contacts_.size(), IoError,
                  "checkpoint: the DEM's dashpots do not match its contacts");
    for (std::size_t k = 0; k < dashpots.size(); ++k) {
      self.contacts_[k].dashpot_normal = dashpots[k](0);
      self.contacts_[k].dashpot_shear = dashpots[k](1);
    }
    self.index_zoned_blocks();
  }
}

}  // namespace fissure::dem
