// A deformable block of the explicit DEM (docs/dem.md, "Deformable
// blocks"; Cundall and Hart 1992, UDEC's fully deformable blocks): nodes
// with lumped masses, moved by central differences with local or viscous
// damping (central_difference.h), and triangular constant-strain zones of
// a linear elastic, isotropic material in plane strain.
//
// Each step, UDEC's way (incremental, the configuration updated):
//   1. zones: the strain increment d eps = sym(grad v^{n-1/2}) dt and the
//      rotation theta = (d u_y/dx - d u_x/dy) / 2 from the half-step
//      velocities, the gradient over the increment's midpoint geometry
//      (Hughes and Winget 1980); the deviatoric stress turned with the
//      material by 2 atan(theta / 2) (Jaumann, objectively: a rigid turn of
//      any size strains nothing and keeps the stress in the material's
//      axes, its norm to round-off) and incremented by 2 G dev(d eps);
//   2. the volumetric part against locking: a constant-strain triangle
//      locks as nu -> 1/2 (a triangulation has about as many zones as
//      displacement unknowns, so incompressible zones leave it no motion).
//      UDEC's mixed discretization (Marti and Cundall 1982) averages the
//      volumetric strain over the two overlaid triangle pairs of a
//      quadrilateral, which an arbitrary triangulation does not have. Here
//      the volumetric strain is averaged at the nodes instead (Bonet and
//      Burton 1998, "average nodal pressure"): each node's volume change is
//      the sum of a third of its zones' (d V_a = sum A_z d eps_v / 3),
//      its pressure p_a grows by K d V_a / V_a, and a zone's mean stress is
//      the mean of its three nodes' pressures. It is the linearization of a
//      potential (deviatoric energy per zone, volumetric energy per node),
//      so energy is conserved, and a uniform strain stays exact (the patch
//      test). VolumetricStrain::PerZone keeps the plain constant-strain
//      triangle, for comparison;
//   3. nodal forces from the zones' stresses (f_a = -A sigma grad N_a),
//      added to the external ones (contacts, tractions; add_force) and the
//      weight;
//   4. nodes: v^{n+1/2} and x^{n+1} (central_difference.h); a fixed
//      component keeps its velocity (zero: a support; or a given one).
// Small strains per step, any rotation. Stresses are tension positive (Pa).
//
// The block also keeps the energy balance of the discrete motion (kinetic,
// strain, dissipated by the damping, work of the external forces, the
// weight and the supports), which closes to O(dt^2).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/base/errors.h"
#include "mechanics/dem/central_difference.h"
#include "mechanics/dem/zone_mesh.h"

namespace fissure::dem {

/// Linear elastic, isotropic rock of a zoned block (plane strain).
struct ZoneMaterial {
  double young = 0;    ///< E, Pa
  double poisson = 0;  ///< nu, in (-1, 1/2)
  double density = 0;  ///< rho, kg/m^3

  double bulk() const { return young / (3 * (1 - 2 * poisson)); }  ///< K, Pa
  double shear() const { return young / (2 * (1 + poisson)); }     ///< G, Pa
  double constrained() const { return bulk() + 4 * shear() / 3; }  ///< K + 4G/3, Pa
  double p_wave_speed() const;                                     ///< m/s
};

/// A zone's stress, tension positive, Pa (zz: out of plane, plane strain).
struct ZoneStress {
  double xx = 0, yy = 0, xy = 0, zz = 0;
};

enum class VolumetricStrain {
  NodalAverage,  ///< Bonet and Burton's average nodal pressure (default)
  PerZone,       ///< the plain constant-strain triangle (locks as nu -> 1/2)
};

/// Energies per metre of thickness (J/m) at the time of the last step.
struct EnergyBalance {
  double kinetic = 0;        ///< with the mean of the two half-step velocities
  double strain = 0;         ///< elastic, of the zones' stresses
  double dissipated = 0;     ///< by the damping, since the first step
  double external_work = 0;  ///< of add_force's forces, the weight, the supports
  double gravity_work = 0;   ///< the weight's share of external_work
  double contact_work = 0;   ///< add_contact_force's share of external_work
};

/// The unbalanced force of the last step (N/m), for equilibrium ratios
/// (UDEC's: largest / mean applied).
struct UnbalancedForce {
  double largest = 0;       ///< the largest over the free nodes (fixed components left out)
  double mean_applied = 0;  ///< the mean over the nodes of the sum of the
                            ///< magnitudes of the forces on each (zones, external, weight)
};

class ZonedBlock {
 public:
  /// Nodes at rest, stress-free; lumped masses rho A / 3 from each zone.
  ZonedBlock(ZoneMesh mesh, const ZoneMaterial& material,
             VolumetricStrain volumetric = VolumetricStrain::NodalAverage);

  int n_nodes() const { return static_cast<int>(position_.size()); }
  int n_zones() const { return static_cast<int>(zones_.size()); }
  const std::vector<std::array<int, 3>>& zones() const { return zones_; }
  /// Loop 0 the outer boundary (counter-clockwise), then the holes (clockwise).
  const std::vector<std::vector<int>>& boundary() const { return boundary_; }
  const std::vector<int>& corner_nodes() const { return corner_nodes_; }
  const ZoneMaterial& material() const { return material_; }

  const std::vector<Vec2>& positions() const { return position_; }
  /// At the last half step (before the first step: the initial velocities).
  const std::vector<Vec2>& velocities() const { return velocity_; }
  const std::vector<double>& masses() const { return mass_; }
  /// The boundary at the current positions, as a Polygon (loops as boundary()).
  Polygon boundary_polygon() const;

  void set_velocity(int node, const Vec2& velocity) { velocity_[node] = velocity; }
  /// A fixed component keeps its velocity (set_velocity) through the steps.
  void fix(int node, bool x, bool y);
  /// Every zone at the same stress (an initial stress; out-of-plane included).
  void set_stress(const ZoneStress& stress);
  ZoneStress stress(int zone) const;

  /// Adds an external force (N/m) on a node for the next step only.
  void add_force(int node, const Vec2& force) { external_[node] += force; }
  /// The same for a contact's force, whose work the energy balance keeps
  /// apart (contact_work: the contacts' own ledger holds it, dem_energy.h).
  void add_contact_force(int node, const Vec2& force) {
    external_[node] += force;
    contact_[node] += force;
  }
  /// Moves every node away from `centre` by `factor` (a free uniform
  /// expansion, the heat's on a block whose zones do not see temperature):
  /// no strain, no stress.
  void scale_about(const Vec2& centre, double factor);
  /// Every free node at rest (a solved quasi-static state).
  void stop();
  /// Density scaling: the nodes' masses in their motion (not in their
  /// weight), each at least its own; empty: their own.
  void set_inertial_masses(std::vector<double> masses) { inertial_ = std::move(masses); }
  /// The zones' bound on the squared highest frequency, (2 /
  /// critical_time_step)^2 (1/s^2).
  double zones_omega_squared() const { return 4 / (critical_step_ * critical_step_); }
  /// The zones' stresses averaged over the block's area (Pa).
  ZoneStress mean_stress() const;
  /// The centre of the nodes' masses, and the block's mean motion about it
  /// (x, y velocity and the rate of turn sum m r x v / sum m r^2).
  Vec2 centre_of_mass() const;
  Eigen::Vector3d mean_motion(const Vec2& centre_of_mass) const;

  /// One explicit step, update_zones then move_nodes (gravity: m/s^2).
  void step(double dt, const Vec2& gravity, const DampingControls& damping,
            double stiffness_damping = 0);
  /// The step's first half: the zones' stresses at the current positions
  /// x^n from the half-step velocities v^{n-1/2} (none before the first
  /// step), and their nodal forces. Neither moves a node, so contacts may
  /// add their forces before or after it. `stiffness_damping` beta (s):
  /// Rayleigh's stiffness-proportional damping, beta times the step's
  /// elastic stress rate added to the stresses the forces come from (not
  /// to the stored ones); what it dissipates is in the balance.
  void update_zones(double dt, double stiffness_damping = 0);
  /// The second half: velocities v^{n+1/2} and positions x^{n+1} from the
  /// zones' forces, add_force's and the weight; clears add_force's.
  void move_nodes(double dt, const Vec2& gravity, const DampingControls& damping);

  /// The largest stable step of the undamped nodes under the zones' own
  /// stiffness: the smallest over the zones of 2 / omega_z, omega_z the
  /// zone's highest frequency with its share of the lumped masses (the
  /// element eigenvalue bound, which holds for the assembled block and for
  /// the nodal average, whose volumetric stiffness is softer). The caller
  /// takes the smallest over the blocks and contacts, times a safety factor.
  double critical_time_step() const { return critical_step_; }

  /// The strain energy of the current stresses (J/m).
  double strain_energy() const;
  EnergyBalance energy() const;
  const UnbalancedForce& unbalanced_force() const { return unbalanced_; }

  /// Everything the next steps depend on, the mesh's topology and masses
  /// included (a process's checkpoint, core/io/checkpoint.h): read into a
  /// block of any mesh, it becomes the written one.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);

 private:
  void update_stresses(double dt, double stiffness_damping);
  void add_internal_forces();

  ZoneMaterial material_;
  VolumetricStrain volumetric_;
  double bulk_ = 0, shear_ = 0, critical_step_ = 0;
  std::vector<std::array<int, 3>> zones_;
  std::vector<std::vector<int>> boundary_;
  std::vector<int> corner_nodes_;

  // Nodes.
  std::vector<Vec2> position_, velocity_, external_, internal_;
  std::vector<Vec2> contact_;  ///< add_contact_force's share of external_
  /// The stiffness-proportional damping's share of internal_ (empty without it).
  std::vector<Vec2> viscous_force_;
  std::vector<double> mass_;
  std::vector<double> inertial_;     ///< density scaling's masses (empty: mass_)
  std::vector<std::uint8_t> fixed_;  ///< bit 0: x, bit 1: y
  std::vector<double> pressure_;     ///< mean stress p_a (NodalAverage), Pa
  std::vector<double> volume_;       ///< a third of the areas of the node's zones, m^2
  std::vector<double> volume_change_;
  std::vector<double> applied_;  ///< sum of the magnitudes of the zones' forces

  // Zones.
  struct Deviator {
    double xx = 0, yy = 0, xy = 0, zz = 0;
  };
  std::vector<Deviator> deviator_;
  std::vector<double> zone_pressure_;  ///< PerZone only
  std::vector<double> area_;           ///< at the last stress update
  /// The stiffness-proportional damping's stresses (xx, yy, xy) of the
  /// last update (empty without it).
  std::vector<Eigen::Vector3d> viscous_stress_;

  bool started_ = false;
  EnergyBalance energy_;
  double last_dissipated_ = 0, last_external_work_ = 0;  ///< the last step's shares
  double last_gravity_work_ = 0, last_contact_work_ = 0;
  UnbalancedForce unbalanced_;
};

template <class Self, class Archive>
void ZonedBlock::checkpoint(Self& self, Archive& a) {
  // Lists of fixed-width rows: the topology flattened, loops with offsets.
  std::vector<int> zones, loops, loop_ends;
  std::vector<Eigen::Vector4d> deviators;
  if constexpr (!Archive::reading) {
    for (const auto& z : self.zones_) zones.insert(zones.end(), z.begin(), z.end());
    for (const auto& loop : self.boundary_) {
      loops.insert(loops.end(), loop.begin(), loop.end());
      loop_ends.push_back(static_cast<int>(loops.size()));
    }
    for (const Deviator& d : self.deviator_) deviators.emplace_back(d.xx, d.yy, d.xy, d.zz);
  }
  a("zones", zones);
  a("boundary", loops);
  a("boundary_ends", loop_ends);
  a("corner_nodes", self.corner_nodes_);
  a("positions", self.position_);
  a("velocities", self.velocity_);
  a("masses", self.mass_);
  a("fixed", self.fixed_);
  a("pressures", self.pressure_);
  a("volumes", self.volume_);
  a("deviators", deviators);
  a("zone_pressures", self.zone_pressure_);
  a("areas", self.area_);
  a("critical_step", self.critical_step_);
  a("started", self.started_);
  a("kinetic", self.energy_.kinetic);
  a("dissipated", self.energy_.dissipated);
  a("external_work", self.energy_.external_work);
  a("last_dissipated", self.last_dissipated_);
  a("last_external_work", self.last_external_work_);
  // The work's shares (absent from checkpoints of before them: from zero).
  bool shares = true;
  if constexpr (Archive::reading) shares = a.has("gravity_work");
  if (shares) {
    a("gravity_work", self.energy_.gravity_work);
    a("contact_work", self.energy_.contact_work);
    a("last_gravity_work", self.last_gravity_work_);
    a("last_contact_work", self.last_contact_work_);
  }
  a("largest_unbalanced", self.unbalanced_.largest);
  a("mean_applied", self.unbalanced_.mean_applied);
  if constexpr (Archive::reading) {
    const std::size_t n = self.position_.size(), nz = zones.size() / 3;
    FISSURE_CHECK(zones.size() % 3 == 0 && deviators.size() == nz && self.area_.size() == nz &&
                      self.zone_pressure_.size() == nz && self.velocity_.size() == n &&
                      self.mass_.size() == n && self.fixed_.size() == n &&
                      self.pressure_.size() == n && self.volume_.size() == n,
                  IoError, "checkpoint: a zoned block's nodes and zones do not match");
    self.zones_.resize(nz);
    for (std::size_t z = 0; z < nz; ++z)
      self.zones_[z] = {zones[3 * z], zones[3 * z + 1], zones[3 * z + 2]};
    self.boundary_.clear();
    int begin = 0;
    for (int end : loop_ends) {
      self.boundary_.emplace_back(loops.begin() + begin, loops.begin() + end);
      begin = end;
    }
    self.deviator_.resize(nz);
    for (std::size_t z = 0; z < nz; ++z)
      self.deviator_[z] = {deviators[z](0), deviators[z](1), deviators[z](2), deviators[z](3)};
    self.external_.assign(n, Vec2::Zero());
    self.contact_.assign(n, Vec2::Zero());
    self.internal_.assign(n, Vec2::Zero());
    self.volume_change_.assign(n, 0.0);
    self.applied_.assign(n, 0.0);
  }
}

}  // namespace fissure::dem
