// The splitting scheme that advances the processes together (theory.md 6;
// the scene's `coupling` section, docs/architecture.md "Coupling").
//
// Schemes, for a coupling step [t, t + dt] and the processes in `order`:
//  * lie: each process advances once, from the state the previous ones left
//    (first order in dt, theory.md 6.1);
//  * strang: the processes that advance every step sweep forward with half
//    steps [t, t + dt/2], the last of them takes the full step [t, t + dt],
//    and the others sweep back with half steps [t + dt/2, t + dt] in reverse
//    order (second order for smooth problems);
//  * iterated: the lie sweep is repeated from the step's start (the shared
//    state and every process's inner state, StepRollback) until the values
//    the processes exchange (Process::exchanged_values) have stopped
//    changing, each field to its own tolerances (field_convergence.h), with
//    Aitken or fixed relaxation of what the earlier processes read
//    (relaxation.h).
//
// Sub-cycling (theory.md 6.2): a process with a coupling interval T > 0 (or
// `own`: T is the step it proposes when it starts an interval) is a slow
// process. It advances once, over everything since its last update, in the
// first coupling step that completes an interval (or that reaches the end
// of the run); in the steps in between it is skipped and what it wrote stays
// in the shared state, frozen. It takes its own steps within that span: if
// it rejects the span (Retry), it advances in steps of at most what it asks
// for and proposes, until the span is covered. In a strang step it advances
// once, in the forward sweep (first order in its interval). The coupling
// step is the smallest step that the processes without an interval propose,
// shortened to land on the end of an `own` interval.
//
// A Retry from a process that advances every step, or a non-finite state
// after the step, rejects the coupling step: everything is rolled back and
// the step is cut (a retry asked for a half step of strang is scaled to the
// coupling step).
//
// Quasi-static processes (coupling.quasi_static): at each of its updates
// such a process takes its own steps in pseudo-time, all ending at the
// update's end (so its loads are those of the end), until no block point
// moves faster than max_speed or max_steps were taken; its velocities are
// then zeroed and the run's clock has not moved. Its step does not set the
// coupling step; in a strang step it advances once, in the forward sweep. Wall times are measured
// per process for summary.json and never drive a decision, so that runs stay reproducible to the
// bit.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/process/process.h"
#include "core/scene/scene.h"
#include "coupling/field_convergence.h"
#include "coupling/relaxation.h"

namespace fissure {

class StepRollback;

class Splitting {
 public:
  /// `processes` in the order they advance; `coupling` gives the scheme and
  /// their intervals; `end_time` ends every interval early; a step cut below
  /// `min_step` ends the run.
  Splitting(std::vector<Process*> processes, const CouplingSettings& coupling, double end_time,
            double min_step);

  /// Starts every interval at the state's time (after initialize).
  void start(const RockMass& state);

  /// The next coupling step (s) from state.time: the smallest step that the
  /// processes without an interval propose (infinity when none has a limit),
  /// landing on the end of an `own` interval.
  double proposed_dt(const RockMass& state) const;

  /// One attempt at the coupling step [t, t + dt]: every process that is
  /// due advances as the scheme says. On Retry everything is as it was
  /// (the state and the processes; the intervals are not advanced).
  StepReport advance(RockMass& state, double t, double dt);

  /// The coupling step from state.time of at most dt, cut as the processes
  /// ask until it succeeds; sets state.time. Returns the number of cuts;
  /// throws DivergenceError when a cut would go below min_step.
  long step(RockMass& state, double dt);

  /// The scheme, order, intervals, per process its updates, the coupling
  /// steps it was skipped in, its own sub-steps and their retries and its
  /// wall time; the wall time of the step snapshots; the iterated scheme's
  /// passes. For summary.json.
  nlohmann::json statistics() const;

  /// Each process's last update, interval and counts (core/io/checkpoint.h).
  template <class Archive>
  void checkpoint(Archive& a) {
    const std::size_t n = stages_.size();
    a.list("stages", stages_, [](auto& e, auto& s) {
      e("last", s.last);
      e("interval", s.interval);
      e("updates", s.updates);
      e("skipped", s.skipped);
      e("sub_steps", s.sub_steps);
      e("sub_step_retries", s.sub_step_retries);
      e("seconds", s.seconds);
      e("not_at_rest", s.not_at_rest);
      e("last_speed", s.last_speed);
    });
    FISSURE_CHECK(
        stages_.size() == n, IoError,
        "the checkpoint's coupling has " << stages_.size() << " processes, the scene " << n);
    auto passes = a.section("iteration");
    passes("passes", passes_.total);
    passes("max_per_step", passes_.max_per_step);
    passes("not_converged", passes_.not_converged);
    passes("frozen", passes_.frozen);
    convergence_.checkpoint(passes);
    a("rollback_seconds", rollback_seconds_);
  }

 private:
  struct Stage {
    Process* process = nullptr;
    double interval = 0;  ///< s; 0 = every coupling step
    bool own = false;     ///< the interval is the process's own proposed step
    double last = 0;      ///< end of its last update (s)
    long updates = 0;
    long skipped = 0;
    long sub_steps = 0;         ///< accepted advance() calls
    long sub_step_retries = 0;  ///< Retries absorbed within its span
    double seconds = 0;         ///< wall time in advance() (never drives a decision)
    long pending_sub_steps = 0, pending_retries = 0;  ///< of the current attempt
    /// Brought to rest at each update in pseudo-time (coupling.quasi_static).
    bool quasi_static = false;
    long not_at_rest = 0;   ///< updates that ended at max_steps still moving
    double last_speed = 0;  ///< fastest block point after its last update (m/s)
    long pending_not_at_rest = 0;
    double pending_speed = 0;
    bool every_step() const { return interval == 0 && !own; }
    /// Its steps set the coupling step (quasi-static steps are pseudo-time).
    bool paces() const { return every_step() && !quasi_static; }
  };
  /// One advance of one process in a sweep.
  struct Move {
    Stage* stage;
    double t, dt;
  };
  struct Passes {
    long total = 0, max_per_step = 0, not_converged = 0;
    long frozen = 0;  ///< steps whose discrete states were frozen
  };

  bool due(const Stage& s, double t_end) const;
  std::vector<Stage*> due_stages(double t_end);
  /// The scheme's sweep over the due stages (lie order, or strang's).
  std::vector<Move> sweep_plan(const std::vector<Stage*>& due, double t, double dt,
                               bool symmetric) const;
  /// Advances the moves in turn; the first Retry, scaled to the step dt.
  StepReport sweep(RockMass& state, const std::vector<Move>& moves, double dt);
  /// One process over [t, t + dt]: a process that advances every step once;
  /// a sub-cycled one in its own steps until the span is covered.
  StepReport advance_stage(Stage& s, RockMass& state, double t, double dt);
  /// A quasi-static process at the end of [t, t + dt]: its own steps in
  /// pseudo-time until at rest or max_steps, then its velocities zeroed.
  StepReport equilibrate(Stage& s, RockMass& state, double t, double dt);
  /// The shorter step a process asks for within its own steps (a retry it
  /// absorbs, counted); DivergenceError below min_step.
  double own_retry(Stage& s, const StepReport& report, double h, double t);
  StepReport timed_advance(Stage& s, RockMass& state, double t, double dt);
  /// The iterated scheme's passes; `passes` gets their number.
  StepReport iterate(RockMass& state, const std::vector<Stage*>& due, double t, double dt,
                     StepRollback& rollback, long& passes, bool& converged);
  void commit(const std::vector<Stage*>& due, const RockMass& state, double t_end);
  static double own_interval(const Stage& s, const RockMass& state);

  std::vector<Stage> stages_;
  std::optional<CouplingSettings::QuasiStatic> quasi_static_;
  CouplingSettings::Scheme scheme_;
  CouplingSettings::Iteration iteration_;
  Relaxation relaxation_;
  FieldConvergence convergence_;
  /// Each exchanged field's change in the last pass of the current step.
  std::vector<FieldChange> last_changes_;
  double end_time_ = 0;
  double min_step_ = 0;
  Passes passes_;
  double rollback_seconds_ = 0;  ///< taking and restoring snapshots (reported only)
  /// The processes that advanced (Ok) in the current attempt, to roll back.
  std::vector<Process*> advanced_;
};

}  // namespace fissure
