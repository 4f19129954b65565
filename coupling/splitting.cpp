#include "coupling/splitting.h"

#include <algorithm>
#include <limits>

namespace fissure {

LieSplitting::LieSplitting(std::vector<Process*> processes, const CouplingSettings& coupling,
                           double end_time)
    : end_time_(end_time) {
  for (Process* p : processes) {
    const auto it = coupling.intervals.find(p->name());
    stages_.push_back({p, it == coupling.intervals.end() ? 0.0 : it->second});
  }
}

void LieSplitting::start(double t0) {
  for (Stage& s : stages_) s.last = t0;
}

double LieSplitting::proposed_dt(const RockMass& state) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const Stage& s : stages_)
    if (s.interval == 0) dt = std::min(dt, s.process->proposed_dt(state));
  return dt;
}

bool LieSplitting::due(const Stage& s, double t_end) const {
  // Up to a relative 1e-9 of the interval, as the steps that fill it add
  // up with round-off; the end of the run closes every interval.
  return s.interval == 0 || t_end - s.last >= s.interval * (1 - 1e-9) ||
         t_end >= end_time_ * (1 - 1e-12);
}

StepReport LieSplitting::advance(RockMass& state, double t, double dt) {
  const double t_end = t + dt;
  for (Stage& s : stages_) {
    if (!due(s, t_end)) continue;
    // A slow process spans everything since its last update; the others
    // take the coupling step itself (dt exactly, not a difference of times).
    const StepReport report = s.interval == 0 ? s.process->advance(state, t, dt)
                                              : s.process->advance(state, s.last, t_end - s.last);
    if (report.status == StepReport::Status::Retry) return report;
  }
  for (Stage& s : stages_) {
    if (due(s, t_end)) {
      s.last = t_end;
      ++s.updates;
    } else {
      ++s.skipped;
    }
  }
  return {};
}

nlohmann::json LieSplitting::statistics() const {
  nlohmann::json j;
  j["scheme"] = "lie";
  for (const Stage& s : stages_) {
    j["order"].push_back(s.process->name());
    j["intervals"][s.process->name()] = s.interval;
    j["updates"][s.process->name()] = s.updates;
    j["skipped_steps"][s.process->name()] = s.skipped;
  }
  return j;
}

}  // namespace fissure
