// The explicit distinct-element method as a Fissure process (docs/dem.md;
// Cundall and Hart 1992, Itasca's UDEC): rigid or deformable (zoned,
// `dem.zone_size`) blocks on joints whose
// contacts follow the scene's joint laws (rockmass/joints/), integrated by
// central differences in cycles of a step below the critical one. One
// update (the process's step in the coupling) is a number of cycles:
//  * dynamic: cycles_per_step cycles of real time (fewer when the
//    coupling's step is shorter), with the loads of the update's end;
//  * quasi-static (`solve_ratio`): cycles in pseudo-time until the
//    unbalanced-force ratio is below the target (UDEC's "solve ratio").
// It writes what any block process writes (the blocks' geometry, motion
// and average stress, the contacts), and reads the flow's pressure loads
// and the heat's free thermal strain (a rigid block expands uniformly
// about its centroid), so the flow's HM coupling and the heat work with it
// unchanged.
#pragma once

#include <optional>
#include <vector>

#include "core/io/block_monitors.h"
#include "core/process/process.h"
#include "mechanics/dem/dem_settings.h"
#include "mechanics/dem/dem_system.h"
#include "mechanics/dem/zoned_block_loads.h"
#include "rockmass/fields/contact_results.h"
#include "rockmass/fields/interface_ties.h"

namespace fissure::dem {

class DemProcess final : public Process {
 public:
  explicit DemProcess(const Scene& scene);

  std::string name() const override { return "dem"; }
  std::vector<std::string> reads() const override;
  std::vector<std::string> writes() const override;
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass& state) const override;
  StepReport advance(RockMass& state, double t, double dt) override;
  const MonitorSource* monitors() const override { return &monitors_; }
  ResultsPart* results() override { return &results_; }
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass& state) const override;
  /// With ties to a continuum: the forces it gives it (interface_ties.h).
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override;
  void save(CheckpointWriter& out, const RockMass& state) const override;
  void restore(CheckpointReader& in, RockMass& state) override;

  const DemSystem& system() const { return *system_; }

 private:
  /// The blocks and laws of `state`, the system's settings.
  void build_system(const RockMass& state);
  /// The cycle's step: the given one, or the safety factor of the critical one.
  double cycle_step() const;
  /// The step of a solved update's cycles: with density scaling, the
  /// safety factor of the blocks' largest natural step after scaling the
  /// others' inertia to it; otherwise cycle_step().
  double solve_step();
  /// Point loads at t and the flow's pressure loads, per rigid block, and
  /// on the zoned blocks' nodes.
  std::vector<BlockLoad> external_loads(const RockMass& state, double t,
                                        std::vector<std::vector<Vec2>>& nodal) const;
  /// Each material point on a zoned block: its zone and weights there.
  void locate_points(const RockMass& state);
  /// The heat's free thermal strain: each block scaled about its centroid
  /// by the change since the last update; returns each block's factor.
  std::vector<double> apply_thermal_strain(const RockMass& state);
  /// The blocks, points (moved with their block's turn and scale) and
  /// contacts into the shared state.
  void publish(RockMass& state, const std::vector<Vec2>& centroids_before,
               const std::vector<double>& angles_before, const std::vector<double>& scales) const;
  void publish_contacts(RockMass& state) const;
  /// The step's ties as the cycles apply them: each spring of `springs` on
  /// its rigid block's polygon edge, or between the two boundary nodes of
  /// its zoned block that its start point lies between.
  std::vector<DemTie> dem_ties(const std::vector<TieSpring>& springs) const;
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);

  DemControls c_;
  std::vector<PointLoad> point_loads_;
  int first_load_point_ = 0;
  double rounding_ = 0, margin_ = 0;
  std::unique_ptr<DemSystem> system_;
  /// Per material point of the state: where it is in its zoned block's
  /// zones (zone -1: not on a zoned block).
  std::vector<PointInZone> point_zones_;
  /// Per block: the free thermal strain applied so far.
  std::vector<double> thermal_strain_;
  /// Reduced (halved) after an update whose contacts overlapped too deeply,
  /// grown back towards 1 after each good one.
  double step_scale_ = 1;
  BlockMonitors monitors_;
  ContactResults results_;
  InterfaceTies ties_;  ///< block edges tied to a continuum interface
  /// Per tied edge of a zoned block (ties_'s edges): its boundary nodes from
  /// corner to corner and their places on the edge (0 to 1) at the start.
  std::vector<std::vector<std::pair<double, int>>> tied_edge_nodes_;
  bool first_step_ = true;

  struct Counters {
    long updates = 0, retries = 0, unsolved_updates = 0;
    double largest_ratio_at_end = 0;  ///< of the updates' last cycles
    double max_overlap = 0;           ///< m
    double seconds = 0;
  } counters_;
};

}  // namespace fissure::dem
