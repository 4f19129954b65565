#include "coupling/splitting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/stopwatch.h"
#include "core/scene/coupling_names.h"
#include "core/scene/time_limits.h"
#include "core/state/monitor_values.h"
#include "core/state/non_finite.h"
#include "coupling/step_rollback.h"

namespace fissure {

namespace {

using Scheme = CouplingSettings::Scheme;

/// A step `dt` that would leave less than a sliver of `remaining`: all of it.
double land_on(double dt, double remaining) {
  return dt >= remaining - 1e-6 * dt ? remaining : dt;
}

}  // namespace

Splitting::Splitting(std::vector<Process*> processes, const CouplingSettings& coupling,
                     double end_time, double min_step)
    : scheme_(coupling.scheme),
      iteration_(coupling.iteration),
      relaxation_(coupling.iteration),
      convergence_(coupling.iteration),
      end_time_(end_time),
      min_step_(min_step) {
  quasi_static_ = coupling.quasi_static;
  for (Process* p : processes) {
    Stage s;
    s.process = p;
    s.quasi_static = runs_in_pseudo_time(coupling, p->name());
    // Pseudo-time is for the blocks' inertia: a process that moves no block
    // would cover one own step of each span and the rest of the run's time
    // would be lost.
    const std::vector<std::string> writes = p->writes();
    FISSURE_CHECK(
        !s.quasi_static ||
            std::find(writes.begin(), writes.end(), block_fields::kinematics) != writes.end(),
        SceneError,
        "coupling.quasi_static.processes: found '"
            << p->name()
            << "', which moves no blocks; expected the processes that move blocks (that write "
               "block_kinematics): its steps in pseudo-time would not cover the run's time");
    const auto it = coupling.intervals.find(p->name());
    s.interval = it == coupling.intervals.end() ? 0.0 : it->second;
    s.own = coupling.own_intervals.count(p->name()) > 0;
    stages_.push_back(s);
  }
}

double Splitting::own_interval(const Stage& s, const RockMass& state) {
  const double dt = s.process->proposed_dt(state);
  FISSURE_CHECK(dt > 0, std::logic_error,
                s.process->name() << " proposed a step of " << dt << " s; expected > 0");
  return dt;
}

void Splitting::start(const RockMass& state) {
  for (Stage& s : stages_) {
    s.last = state.time;
    if (s.own) s.interval = own_interval(s, state);
  }
}

double Splitting::proposed_dt(const RockMass& state) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const Stage& s : stages_)
    if (s.paces()) dt = std::min(dt, s.process->proposed_dt(state));
  // An own interval is the step its process asked for: the coupling steps
  // end on it rather than overshoot it.
  for (const Stage& s : stages_) {
    const double remaining = s.last + s.interval - state.time;
    if (s.own && remaining > 0) dt = land_on(dt, remaining);
  }
  return dt;
}

bool Splitting::due(const Stage& s, double t_end) const {
  // Up to a relative 1e-9 of the interval, as the steps that fill it add
  // up with round-off; the end of the run closes every interval.
  return s.every_step() || t_end - s.last >= s.interval * (1 - 1e-9) ||
         t_end >= end_time_ * (1 - 1e-12);
}

std::vector<Splitting::Stage*> Splitting::due_stages(double t_end) {
  std::vector<Stage*> due;
  for (Stage& s : stages_)
    if (this->due(s, t_end)) due.push_back(&s);
  return due;
}

std::vector<Splitting::Move> Splitting::sweep_plan(const std::vector<Stage*>& due, double t,
                                                   double dt, bool symmetric) const {
  // A slow process spans everything since its last update; the others
  // take the coupling step itself (dt exactly, not a difference of times).
  std::vector<Move> moves;
  const Stage* full = nullptr;  // strang: the last process that advances every step
  if (symmetric)
    for (Stage* s : due)
      if (s->paces()) full = s;
  const double half = 0.5 * dt;
  for (Stage* s : due) {
    if (!s->paces())
      moves.push_back({s, s->last, t + dt - s->last});
    else if (!symmetric || s == full)
      moves.push_back({s, t, dt});
    else
      moves.push_back({s, t, half});
  }
  for (auto it = due.rbegin(); symmetric && it != due.rend(); ++it)
    if ((*it)->paces() && *it != full) moves.push_back({*it, t + half, half});
  return moves;
}

StepReport Splitting::timed_advance(Stage& s, RockMass& state, double t, double dt) {
  const Stopwatch clock;
  StepReport report = s.process->advance(state, t, dt);
  s.seconds += clock.seconds();
  if (report.status == StepReport::Status::Ok) {
    ++s.pending_sub_steps;
    if (std::find(advanced_.begin(), advanced_.end(), s.process) == advanced_.end())
      advanced_.push_back(s.process);
  }
  return report;
}

StepReport Splitting::advance_stage(Stage& s, RockMass& state, double t, double dt) {
  if (s.quasi_static) return equilibrate(s, state, t, dt);
  if (s.every_step()) return timed_advance(s, state, t, dt);
  // A slow process covers its span in its own steps: the whole span first,
  // then, after a Retry, what it asks for and what it proposes.
  double h = dt, remaining = dt;
  for (;;) {
    const StepReport report = timed_advance(s, state, t, h);
    if (report.status == StepReport::Status::Retry) {
      h = own_retry(s, report, h, t);
      continue;
    }
    if (h == remaining) return {};
    t += h;
    remaining -= h;
    h = land_on(std::min(s.process->proposed_dt(state), remaining), remaining);
  }
}

double Splitting::own_retry(Stage& s, const StepReport& report, double h, double t) {
  FISSURE_CHECK(report.dt_retry < h && report.dt_retry >= min_step_, DivergenceError,
                s.process->name() << "'s step at t = " << t
                                  << " s cannot be completed: " << report.reason
                                  << " (its step would be cut to " << report.dt_retry
                                  << " s, below time.min_step = " << min_step_ << " s)");
  ++s.pending_retries;
  return report.dt_retry;
}

StepReport Splitting::equilibrate(Stage& s, RockMass& state, double t, double dt) {
  const double t_end = t + dt;
  double speed = std::numeric_limits<double>::infinity();
  double h = s.process->proposed_dt(state);
  for (long steps = 0; steps < quasi_static_->max_steps;) {
    const StepReport report = timed_advance(s, state, t_end - h, h);
    if (report.status == StepReport::Status::Retry) {
      h = own_retry(s, report, h, t_end);
      continue;
    }
    ++steps;
    speed = fastest_block_point(state);
    if (speed <= quasi_static_->max_speed) break;
    h = s.process->proposed_dt(state);
  }
  if (speed > quasi_static_->max_speed) ++s.pending_not_at_rest;
  s.pending_speed = speed;
  for (Block& b : state.blocks) b.velocity.setZero();
  return {};
}

StepReport Splitting::sweep(RockMass& state, const std::vector<Move>& moves, double dt) {
  for (const Move& m : moves) {
    StepReport report = advance_stage(*m.stage, state, m.t, m.dt);
    if (report.status != StepReport::Status::Retry) continue;
    // A retry asked for a half step is a retry of the coupling step.
    if (m.dt != dt) report.dt_retry *= dt / m.dt;
    return report;
  }
  return {};
}

StepReport Splitting::iterate(RockMass& state, const std::vector<Stage*>& due, double t, double dt,
                              StepRollback& rollback, long& passes, bool& converged) {
  const std::vector<Move> moves = sweep_plan(due, t, dt, false);
  // Every due process's exchanged fields in one list; counts[k]: how many
  // are process k's (its section's `exchanges`, the same in every pass).
  std::vector<std::size_t> counts(due.size());
  auto exchanged = [&] {
    std::vector<ExchangedField> fields;
    for (std::size_t k = 0; k < due.size(); ++k) {
      std::vector<ExchangedField> f = due[k]->process->exchanged_values(state);
      counts[k] = f.size();
      fields.insert(fields.end(), std::make_move_iterator(f.begin()),
                    std::make_move_iterator(f.end()));
    }
    return fields;
  };
  // x: the values each pass starts from; first those of the step's start.
  // The first process's are recomputed before anyone reads them, so only
  // the later processes' (from field `first_relaxed` on) are relaxed.
  std::vector<ExchangedField> x = exchanged();
  const std::size_t first_relaxed = due.empty() ? 0 : counts[0];
  relaxation_.reset();
  std::vector<double> scale;  // per relaxed value: its field's tolerance
  // Discrete states frozen in a pass (freeze_states_after) stay frozen for
  // this coupling step only, whichever way it ends.
  struct Freezer {
    const std::vector<Stage*>& due;
    bool on = false;
    void set(bool frozen) {
      if (frozen == on) return;
      for (Stage* s : due) s->process->freeze_discrete_states(frozen);
      on = frozen;
    }
    ~Freezer() { set(false); }
  } freezer{due};
  bool released = false;  // the pass after the frozen ones
  for (passes = 1;; ++passes) {
    if (passes > 1) {
      const Stopwatch clock;
      rollback.restore(state, advanced_);
      rollback_seconds_ += clock.seconds();
      advanced_.clear();
      std::size_t f = first_relaxed;
      for (std::size_t k = 1; k < due.size(); ++k) {
        due[k]->process->set_exchanged_values(state, std::span(x).subspan(f, counts[k]));
        f += counts[k];
      }
    }
    const StepReport report = sweep(state, moves, dt);
    if (report.status == StepReport::Status::Retry) return report;
    std::vector<ExchangedField> produced = exchanged();
    // Nothing that the earlier processes read is exchanged: a second pass
    // would repeat the first to the bit.
    const bool relaxed_any = std::any_of(produced.begin() + first_relaxed, produced.end(),
                                         [](const ExchangedField& f) { return !f.values.empty(); });
    const bool same_layout =
        produced.size() == x.size() &&
        std::equal(x.begin(), x.end(), produced.begin(), [](const auto& a, const auto& b) {
          return a.kind == b.kind && a.values.size() == b.values.size();
        });
    last_changes_.clear();
    if (!relaxed_any) {  // one pass by design: no field is tested
      converged = true;
      return {};
    }
    if (same_layout) {
      last_changes_ = convergence_.measure(x, produced);
      convergence_.record_pass(last_changes_);
    }
    if (released) return {};  // judged by the frozen passes before it
    converged = same_layout && std::all_of(last_changes_.begin(), last_changes_.end(),
                                           [](const FieldChange& c) { return c.converged(); });
    const bool done = converged || passes >= iteration_.max_iterations;
    if (done && freezer.on) {
      // One more pass from the values the frozen passes reached, with the
      // states free again: the state kept then obeys each process's own law
      // (a frozen contact may be in tension), as a Lie sweep from them would.
      freezer.set(false);
      released = true;
      x = std::move(produced);
      continue;
    }
    if (done) return {};
    if (passes == iteration_.freeze_states_after) {
      freezer.set(true);
      ++passes_.frozen;
      relaxation_.reset();  // a new map: the secant of the old one misleads
      scale.clear();
    }
    if (!same_layout) {  // a field appeared or changed its size: start afresh
      x = std::move(produced);
      relaxation_.reset();
      scale.clear();
      continue;
    }
    // Each field's residuals divided by its tolerance at the step's first
    // relaxation, held through the step: Aitken's omega from residuals of
    // one scale is the secant step of the plain ones.
    const bool first_relaxation = scale.empty();
    std::vector<double> y, r;
    for (std::size_t f = first_relaxed; f < x.size(); ++f)
      for (std::size_t i = 0; i < x[f].values.size(); ++i) {
        y.push_back(x[f].values[i]);
        r.push_back(produced[f].values[i] - x[f].values[i]);
        if (first_relaxation) scale.push_back(last_changes_[f].tolerance);
      }
    relaxation_.relax(y, r, scale);
    std::size_t j = 0;
    for (std::size_t f = 0; f < x.size(); ++f)
      if (f < first_relaxed)
        x[f] = std::move(produced[f]);
      else
        for (double& v : x[f].values) v = y[j++];
  }
}

StepReport Splitting::advance(RockMass& state, double t, double dt) {
  const double t_end = t + dt;
  const std::vector<Stage*> due = due_stages(t_end);
  std::vector<Process*> processes;
  for (const Stage* s : due) processes.push_back(s->process);
  // A later process's Retry or a non-finite state must undo the earlier
  // processes' work; a lone process's Retry leaves its state untouched.
  Stopwatch clock;
  StepRollback rollback(state, processes, processes.size() > 1);
  rollback_seconds_ += clock.lap();
  for (Stage& s : stages_) s.pending_sub_steps = s.pending_retries = s.pending_not_at_rest = 0;
  advanced_.clear();
  long passes = 0;
  bool converged = true;
  StepReport report = scheme_ == Scheme::Iterated
                          ? iterate(state, due, t, dt, rollback, passes, converged)
                          : sweep(state, sweep_plan(due, t, dt, scheme_ == Scheme::Strang), dt);
  if (report.status == StepReport::Status::Ok) {
    // Nothing non-finite is ever written (issue 22, item 4).
    const std::string bad = non_finite_block(state);
    if (!bad.empty()) report = {StepReport::Status::Retry, 0.5 * dt, bad + " after the step"};
  }
  if (report.status == StepReport::Status::Retry) {
    clock.restart();
    rollback.restore(state, advanced_);
    rollback_seconds_ += clock.seconds();
    return report;
  }
  if (scheme_ == Scheme::Iterated) {
    passes_.total += passes;
    passes_.max_per_step = std::max(passes_.max_per_step, passes);
    if (!converged) ++passes_.not_converged;
    convergence_.record_accepted(last_changes_);
  }
  commit(due, state, t_end);
  return report;
}

void Splitting::commit(const std::vector<Stage*>& due, const RockMass& state, double t_end) {
  for (Stage& s : stages_) {
    if (std::find(due.begin(), due.end(), &s) == due.end()) {
      ++s.skipped;
      continue;
    }
    s.last = t_end;
    ++s.updates;
    s.sub_steps += s.pending_sub_steps;
    s.sub_step_retries += s.pending_retries;
    s.not_at_rest += s.pending_not_at_rest;
    if (s.quasi_static) s.last_speed = s.pending_speed;
  }
  // The next own interval, proposed from the state the whole step left.
  for (Stage* s : due)
    if (s->own) s->interval = own_interval(*s, state);
}

long Splitting::step(RockMass& state, double dt) {
  const double t = state.time;
  long cuts = 0;
  for (;;) {
    const StepReport report = advance(state, t, dt);
    if (report.status == StepReport::Status::Ok) {
      state.time = t + dt;
      return cuts;
    }
    ++cuts;
    FISSURE_CHECK(report.dt_retry < dt && report.dt_retry >= min_step_, DivergenceError,
                  "the step at t = " << t << " s cannot be completed: " << report.reason
                                     << " (the time step would be cut to " << report.dt_retry
                                     << " s, below time.min_step = " << min_step_ << " s)");
    dt = report.dt_retry;
  }
}

nlohmann::json Splitting::statistics() const {
  nlohmann::json j;
  j["scheme"] = std::string(name_of(kSchemeNames, scheme_));
  for (const Stage& s : stages_) {
    const std::string& name = s.process->name();
    j["order"].push_back(name);
    j["intervals"][name] = s.own ? nlohmann::json("own") : nlohmann::json(s.interval);
    j["updates"][name] = s.updates;
    j["skipped_steps"][name] = s.skipped;
    j["sub_steps"][name] = s.sub_steps;
    j["sub_step_retries"][name] = s.sub_step_retries;
    j["seconds"][name] = s.seconds;
  }
  if (quasi_static_) {
    j["quasi_static"] = {{"max_speed", quasi_static_->max_speed},
                         {"max_steps", quasi_static_->max_steps}};
    for (const Stage& s : stages_)
      if (s.quasi_static) {
        j["quasi_static"]["processes"].push_back(s.process->name());
        j["quasi_static"]["not_at_rest"][s.process->name()] = s.not_at_rest;
        j["quasi_static"]["last_speed"][s.process->name()] = s.last_speed;
      }
  }
  j["rollback_seconds"] = rollback_seconds_;
  if (scheme_ == Scheme::Iterated) {
    j["iteration"] = {{"tolerance", iteration_.tolerance},
                      {"max_iterations", iteration_.max_iterations},
                      {"relaxation", std::string(name_of(kRelaxationNames, iteration_.relaxation))},
                      {"omega", iteration_.omega},
                      {"passes", passes_.total},
                      {"max_passes_in_a_step", passes_.max_per_step},
                      {"not_converged_steps", passes_.not_converged},
                      {"freeze_states_after", iteration_.freeze_states_after},
                      {"frozen_steps", passes_.frozen},
                      {"fields", convergence_.statistics()}};
  }
  return j;
}

}  // namespace fissure
