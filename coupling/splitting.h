// The splitting scheme that advances the processes together (theory.md 6;
// the scene's `coupling` section, docs/architecture.md "Coupling"). Lie
// splitting: in a coupling step [t, t + dt] each process advances in turn,
// from the state the previous ones left (mechanics, then flow: the flow sees
// the moved blocks, the mechanics the pressures of the last flow update).
//
// Sub-cycling (theory.md 6.2): a process with a coupling interval T > 0 is
// a slow process. It advances once, over everything since its last update,
// in the first coupling step that completes an interval (or that reaches
// the end of the run); in the steps in between it is skipped and what it
// wrote stays in the shared state, frozen. The coupling step is the
// smallest step that the processes without an interval propose.
//
// An iterated scheme (staggered, with relaxation of the exchanged fields,
// theory.md 6.1) fits the same frame: it repeats advance() from the
// coordinator's snapshot of the state until the fields the processes
// declare they write stop changing. It needs each process to restore its
// own inner state too: Process::save/restore (the checkpoints' state, which
// an in-memory HDF5 file could hold between iterations).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/process/process.h"
#include "core/scene/scene.h"

namespace fissure {

class LieSplitting {
 public:
  /// `processes` in the order they advance; `coupling` gives their
  /// intervals; `end_time` ends every interval early.
  LieSplitting(std::vector<Process*> processes, const CouplingSettings& coupling, double end_time);

  /// Starts every interval at the state's time (after initialize).
  void start(double t0);

  /// The next coupling step (s): the smallest step that the processes
  /// without an interval propose (infinity when none has a limit).
  double proposed_dt(const RockMass& state) const;

  /// Advances every process that is due over [t, t + dt]. Stops at the first
  /// Retry and returns it; the caller restores the state and tries a smaller
  /// step (the intervals are not advanced then).
  StepReport advance(RockMass& state, double t, double dt);

  /// The scheme, order, intervals and per process the number of updates and
  /// of coupling steps it was skipped in, for summary.json.
  nlohmann::json statistics() const;

  /// Each process's last update and counts (core/io/checkpoint.h).
  template <class Archive>
  void checkpoint(Archive& a) {
    const std::size_t n = stages_.size();
    a.list("stages", stages_, [](auto& e, Stage& s) {
      e("last", s.last);
      e("updates", s.updates);
      e("skipped", s.skipped);
    });
    FISSURE_CHECK(
        stages_.size() == n, IoError,
        "the checkpoint's coupling has " << stages_.size() << " processes, the scene " << n);
  }

 private:
  struct Stage {
    Process* process = nullptr;
    double interval = 0;  ///< s; 0 = every coupling step
    double last = 0;      ///< end of its last update (s)
    long updates = 0;
    long skipped = 0;
  };
  bool due(const Stage& s, double t_end) const;

  std::vector<Stage> stages_;
  double end_time_ = 0;
};

}  // namespace fissure
