// The one interface every physics module implements (docs/architecture.md 2). It
// lives in core so that physics modules can implement it without depending on
// coupling/ (dependencies point one way: core <- physics <- coupling).
// The coordinator owns time: it asks each process for the step it would take,
// advances them in the order of the coupling scheme, and cuts the step when
// one asks for a retry (SUNDIALS' convention: recoverable vs. unrecoverable
// failures are kept apart). A process owns its output: its monitor columns,
// its part of results.h5/xdmf and its statistics in summary.json.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/process/exchanged_values.h"
#include "core/state/rock_mass.h"

namespace fissure {

class MonitorSource;     // core/io/monitor_source.h
class ResultsPart;       // core/io/results_part.h
class CheckpointWriter;  // core/io/checkpoint.h
class CheckpointReader;

struct StepReport {
  enum class Status {
    Ok,     ///< step accepted, state advanced
    Retry,  ///< step rejected, state untouched; retry with dt_retry
  };
  Status status = Status::Ok;
  double dt_retry = 0;  ///< s, when status == Retry
  std::string reason;   ///< why the step was rejected
};
// Unrecoverable failures (NaN, a singular system) are thrown as
// DivergenceError / SolverError and end the run cleanly.

class Process {
 public:
  virtual ~Process() = default;

  /// Its name in `physics`, in the coupling section and in the output.
  virtual std::string name() const = 0;
  /// The shared fields it reads and writes (names of RockMass's block state,
  /// rock_mass.h, or of RockMass::fields), for the coupling and summary.json.
  virtual std::vector<std::string> reads() const = 0;
  virtual std::vector<std::string> writes() const = 0;

  /// Called before the first step. After an initial stage
  /// (coupling.initial_equilibrium) it is called again on the processes that
  /// did not take part, at the settled state: it must derive everything from
  /// `state` afresh.
  virtual void initialize(RockMass& state) = 0;

  /// The step (s) this process would take next from the current state:
  /// its stability or accuracy limit, e.g. the step that keeps the change it
  /// causes below an allowable increment, adapted from its last steps.
  /// Infinity: no limit. A step that turns out to cause too large a change
  /// is rejected with Retry and a smaller dt_retry.
  virtual double proposed_dt(const RockMass& state) const = 0;

  /// Advance the state from t to t + dt. On Retry the state is unchanged.
  /// The coordinator sets state.time once every process has advanced.
  virtual StepReport advance(RockMass& state, double t, double dt) = 0;

  /// The iterated staggered scheme (coupling.scheme: iterated;
  /// docs/architecture.md "Coupling"): the values of the shared fields it
  /// writes for the other processes, as the last advance left them, one
  /// named block per field of its section's `exchanges` in that order
  /// (core/process/exchanged_values.h). The scheme repeats a coupling step
  /// until each field has stopped changing to its own tolerances, and
  /// relaxes them between passes. Empty (the default): the process takes
  /// part in no convergence test and no relaxation.
  virtual std::vector<ExchangedField> exchanged_values(const RockMass& /*state*/) const {
    return {};
  }
  /// Writes `values` (as exchanged_values returns them) into those fields,
  /// for the processes that read them before this one advances again. Its
  /// own next advance starts from its inner state (restore()), never from
  /// these values.
  virtual void set_exchanged_values(RockMass& /*state*/,
                                    std::span<const ExchangedField> /*values*/) {}
  /// The iterated scheme's freezing (coupling.iteration.freeze_states_after):
  /// while on, every advance holds the discrete states the process chooses
  /// within a step (the DDA's contacts: open, stuck, sliding) at those the
  /// last accepted advance ended with, so that the passes iterate a smooth
  /// map instead of one whose switches cycle. Turned on between two passes,
  /// off when the coupling step ends. No discrete state (the default): nothing.
  virtual void freeze_discrete_states(bool /*on*/) {}

  /// Its columns of monitors.csv; null: none.
  virtual const MonitorSource* monitors() const { return nullptr; }
  /// Its part of results.h5 / results.xdmf; null: none.
  virtual ResultsPart* results() { return nullptr; }
  /// Counters and timings for summary.json.
  virtual nlohmann::json statistics() const = 0;
  /// Energy terms (J per unit thickness) for summary.json; empty if none.
  virtual nlohmann::json energy(const RockMass& state) const = 0;

  /// Its part of a checkpoint (core/io/checkpoint.h): its inner state, its
  /// counters and the shared fields it writes, everything its next steps
  /// depend on, so that a restarted run continues to the bit.
  virtual void save(CheckpointWriter& out, const RockMass& state) const = 0;
  /// Restores what save() wrote. Called after initialize(), once the
  /// coordinator has restored the blocks, the points and the time.
  virtual void restore(CheckpointReader& in, RockMass& state) = 0;
};

}  // namespace fissure
