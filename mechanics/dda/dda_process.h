// Shi's two-dimensional Discontinuous Deformation Analysis as a Fissure
// process (theory.md section 1). One step:
//   1. contacts of the start-of-step geometry, with their history, and the
//      step's friction of each contact on a joint with a law, from its law's
//      state (contact_laws.h);
//   2. the step's block system (inertia, elasticity, stresses, thermal
//      strain, loads);
//   3. open-close iteration: solve, re-classify contacts, until no contact
//      changes state (retry with dt/3 after max_open_close_iterations);
//   4. reject the step (retry with a smaller dt) when a vertex would move more
//      than g2 w;
//   5. update velocities, geometry, stresses and the contacts' law states;
//      let dt grow back towards g1.
#pragma once

#include <optional>
#include <vector>

#include "core/io/block_monitors.h"
#include "core/io/results_part.h"
#include "core/process/process.h"
#include "mechanics/dda/block_system.h"
#include "mechanics/dda/contact_detection.h"
#include "mechanics/dda/contact_laws.h"
#include "mechanics/dda/dda_energy.h"
#include "mechanics/dda/dda_parameters.h"
#include "mechanics/dda/ejected_blocks.h"
#include "mechanics/dda/ground_motion.h"
#include "mechanics/dda/thermal_strain.h"
#include "rockmass/fields/contact_results.h"

namespace fissure::dda {

class DdaProcess final : public Process {
 public:
  explicit DdaProcess(const Scene& scene);

  std::string name() const override { return "mechanics"; }
  std::vector<std::string> reads() const override;
  std::vector<std::string> writes() const override;
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass&) const override { return next_dt_; }
  StepReport advance(RockMass& state, double t, double dt) override;
  /// The motion of each monitor's point and the stress of its block.
  const MonitorSource* monitors() const override { return &monitors_; }
  /// The contacts of each frame.
  ResultsPart* results() override { return &results_; }
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass& state) const override;
  void save(CheckpointWriter& out, const RockMass& state) const override;
  void restore(CheckpointReader& in, RockMass& state) override;
  /// Holds every contact in the state the last accepted step ended with.
  void freeze_discrete_states(bool on) override;
  /// With ties to a continuum: the forces it gives it (interface_ties.h).
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override;

  const DdaParameters& parameters() const { return p_; }
  const std::vector<DdaContact>& contacts() const { return contacts_; }

 private:
  StepReport retry(double dt, std::string reason);
  /// Step 3 of advance(): the open-close iteration on the step's contacts,
  /// with the augmented Lagrangian's passes (3b); its iterations and held
  /// contacts, and the step's retry when it did not converge or the linear
  /// solver failed.
  struct ContactSolve {
    int iterations = 0, held = 0;
    std::optional<StepReport> retry;
  };
  ContactSolve solve_contacts(RockMass& state, std::vector<DdaContact>& contacts, double t,
                              double dt);
  void commit(RockMass& state, const std::vector<Vector6>& increments, double t_end, double dt);
  void publish_contacts(RockMass& state) const;
  /// A fixed block that follows the ground motion (docs/dda.md section 10).
  bool driven(int block) const { return !driven_.empty() && driven_[block]; }
  /// What save() writes (Self const) and restore() reads (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);

  DdaParameters p_;
  /// Per scene joint its law where its contacts carry one (contact_laws.h).
  ContactLaws laws_;
  BlockLoads loads_;
  InterfaceTies ties_;  ///< block vertices tied to a continuum interface
  /// The scene's ground motion (empty without one), the blocks that follow
  /// it (per block; empty without motion), the step's increment of those
  /// blocks, and the viscous boundaries' lines (resolved to edges in
  /// initialize(), BlockLoads::dashpots).
  GroundMotion ground_motion_;
  std::optional<std::vector<std::string>> driven_names_;  ///< none: every fixed block
  std::vector<char> driven_;
  Vector6 driven_increment_ = Vector6::Zero();
  std::vector<ViscousBoundaryControls> viscous_boundaries_;
  std::unique_ptr<BlockSystem> system_;
  std::vector<DdaContact> contacts_;
  /// The free thermal strain applied to each block so far (thermal_strain.h).
  ThermalStrain thermal_;
  EnergyLedger ledger_;
  EjectedBlocks ejected_;  ///< dynamic runs only
  BlockMonitors monitors_;
  ContactResults results_;
  double next_dt_ = 0;
  bool first_step_ = true;
  /// Augmented Lagrangian: the factor on the penalties its stalled passes
  /// have grown to, carried from step to step (dda_process.cpp, 3b).
  double stiffening_ = 1;
  int calm_steps_ = 0;  ///< steps since the last multiplier update
  /// While frozen (freeze_discrete_states): the contacts whose states every
  /// step holds; not part of the process's state (one coupling step only).
  std::optional<std::vector<DdaContact>> frozen_;

  // Statistics.
  struct Counters {
    long steps = 0, open_close_iterations = 0, max_iterations_in_a_step = 0;
    long cuts_open_close = 0, cuts_displacement = 0, cuts_solver = 0, cuts_strain = 0;
    long held_contacts = 0;  ///< accepted with a held state (open_close.h), summed over steps
    /// Augmented Lagrangian: multiplier updates, the most in a step, and the
    /// steps that ended at max_augmentations.
    long augmentations = 0, max_augmentations_in_a_step = 0, augmentation_limit = 0;
    long penalty_growths = 0;  ///< passes that stiffened the step's springs
    /// Steps that took an earlier pass because a later one's open-close
    /// iteration did not converge.
    long augmentation_fallbacks = 0;
    double max_penetration = 0;  ///< largest penetration of a closed contact (m)
    /// The blocks at the start: all, free, and the smallest free block's area
    /// (m^2; generated rock masses have blocks down to mm size).
    long blocks = 0, free_blocks = 0;
    double smallest_free_area = 0;
    double seconds_detection = 0, seconds_assembly_solve = 0, seconds_open_close = 0,
           seconds_update = 0;
  } counters_;
  DetectionCounters detection_;
};

}  // namespace fissure::dda
