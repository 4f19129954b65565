// The coupling as data (coupling/splitting.h, the scene's `coupling`
// section, docs/scene-reference.md section 8): Lie splitting in the given
// order, sub-cycling of a process with a coupling interval (once per
// interval, over the whole interval, and at the end of the run; or over its
// own proposed step), retries that leave the intervals untouched, Strang's
// sweep; the section's checks and the
// deprecated flow.hm.coupling_interval; the named fields of the shared state.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/base/named_values.h"
#include "coupling/process_registry.h"
#include "coupling/splitting.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

using namespace fissure;

namespace {

/// A process that records its advances: (name, t, dt), in call order.
struct Call {
  std::string process;
  double t = 0, dt = 0;
  bool operator==(const Call&) const = default;
};

class RecordingProcess final : public Process {
 public:
  RecordingProcess(std::string name, double step, std::vector<Call>& calls)
      : name_(std::move(name)), step_(step), calls_(calls) {}

  std::string name() const override { return name_; }
  std::vector<std::string> reads() const override { return {}; }
  std::vector<std::string> writes() const override { return writes_; }
  void initialize(RockMass&) override {}
  double proposed_dt(const RockMass&) const override { return step_; }
  StepReport advance(RockMass&, double t, double dt) override {
    calls_.push_back({name_, t, dt});
    if (retries_left_ == 0) return {};
    --retries_left_;
    StepReport r;
    r.status = StepReport::Status::Retry;
    r.dt_retry = dt / 2;
    r.reason = "asked to";
    return r;
  }
  nlohmann::json statistics() const override { return nlohmann::json::object(); }
  nlohmann::json energy(const RockMass&) const override { return nlohmann::json::object(); }
  void save(CheckpointWriter&, const RockMass&) const override {}
  void restore(CheckpointReader&, RockMass&) override {}

  int retries_left_ = 0;
  std::vector<std::string> writes_;

 private:
  std::string name_;
  double step_;
  std::vector<Call>& calls_;
};

CouplingSettings intervals(std::map<std::string, double> by_process) {
  CouplingSettings c;
  c.intervals = std::move(by_process);
  return c;
}

}  // namespace

TEST(coupling, LieSplittingAdvancesEveryProcessInOrderOverTheSameStep) {
  std::vector<Call> calls;
  RecordingProcess fast("fast", 0.5, calls), other("other", 2.0, calls);
  Splitting lie({&other, &fast}, CouplingSettings{}, 10, 1e-9);
  lie.start(RockMass{});
  RockMass state;
  EXPECT_EQ(lie.proposed_dt(state), 0.5);  // the smallest step proposed
  ASSERT_EQ(lie.advance(state, 0, 0.5).status, StepReport::Status::Ok);
  ASSERT_EQ(lie.advance(state, 0.5, 0.5).status, StepReport::Status::Ok);
  EXPECT_EQ(calls,
            (std::vector<Call>{
                {"other", 0, 0.5}, {"fast", 0, 0.5}, {"other", 0.5, 0.5}, {"fast", 0.5, 0.5}}));
}

TEST(coupling, ASubCycledProcessSpansItsIntervalAndTheEndOfTheRun) {
  // The slow process (interval 2.5 s) advances in the first step that
  // completes an interval, over everything since its last update; the run
  // ends at 7.5 s, which closes the last interval early.
  std::vector<Call> calls;
  RecordingProcess fast("fast", 1.0, calls), slow("slow", 0.1, calls);
  Splitting lie({&fast, &slow}, intervals({{"slow", 2.5}}), 7.5, 1e-9);
  lie.start(RockMass{});
  RockMass state;
  // The slow process does not limit the coupling step.
  EXPECT_EQ(lie.proposed_dt(state), 1.0);
  for (double t : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0})
    ASSERT_EQ(lie.advance(state, t, t < 7 - 1e-12 && t >= 6 ? 1.5 : 1.0).status,
              StepReport::Status::Ok);
  std::vector<Call> slow_calls;
  for (const Call& c : calls)
    if (c.process == "slow") slow_calls.push_back(c);
  EXPECT_EQ(slow_calls, (std::vector<Call>{{"slow", 0, 3}, {"slow", 3, 3}, {"slow", 6, 1.5}}));
  const nlohmann::json stats = lie.statistics();
  EXPECT_EQ(stats["updates"]["slow"], 3);
  EXPECT_EQ(stats["skipped_steps"]["slow"], 4);
  EXPECT_EQ(stats["updates"]["fast"], 7);
  EXPECT_EQ(stats["intervals"]["slow"], 2.5);
}

TEST(coupling, ARetryLeavesTheIntervalsWhereTheyWere) {
  std::vector<Call> calls;
  RecordingProcess fast("fast", 1.0, calls), slow("slow", 0.1, calls);
  Splitting lie({&slow, &fast}, intervals({{"slow", 1.0}}), 100, 1e-9);
  lie.start(RockMass{});
  RockMass state;
  fast.retries_left_ = 1;
  // The slow process was due and advanced, then the fast one asked for a
  // retry: the caller restores the state and tries a smaller step from the
  // same start. The slow process is then not due until its interval is
  // complete again, and spans [0, 1] once more.
  EXPECT_EQ(lie.advance(state, 0, 1.0).status, StepReport::Status::Retry);
  EXPECT_EQ(lie.statistics()["updates"]["slow"], 0);
  ASSERT_EQ(lie.advance(state, 0, 0.5).status, StepReport::Status::Ok);  // not due yet
  ASSERT_EQ(lie.advance(state, 0.5, 0.5).status, StepReport::Status::Ok);
  EXPECT_EQ(calls, (std::vector<Call>{{"slow", 0, 1.0},
                                      {"fast", 0, 1.0},
                                      {"fast", 0, 0.5},
                                      {"slow", 0, 1.0},
                                      {"fast", 0.5, 0.5}}));
}

TEST(coupling, StrangSweepsHalfStepsAroundTheLastProcesssFullStep) {
  // Three processes that advance every step and a slow one (interval 1 s,
  // due in this step): a and b half steps forward, c the full step, b and a
  // half steps back; the slow one spans its interval once, in the forward
  // sweep at its place in the order.
  std::vector<Call> calls;
  RecordingProcess a("a", 1.0, calls), slow("slow", 0.1, calls), b("b", 1.0, calls),
      c("c", 1.0, calls);
  CouplingSettings strang = intervals({{"slow", 1.0}});
  strang.scheme = CouplingSettings::Scheme::Strang;
  Splitting splitting({&a, &slow, &b, &c}, strang, 10, 1e-9);
  splitting.start(RockMass{});
  RockMass state;
  ASSERT_EQ(splitting.advance(state, 0, 1.0).status, StepReport::Status::Ok);
  EXPECT_EQ(calls, (std::vector<Call>{{"a", 0, 0.5},
                                      {"slow", 0, 1.0},
                                      {"b", 0, 0.5},
                                      {"c", 0, 1.0},
                                      {"b", 0.5, 0.5},
                                      {"a", 0.5, 0.5}}));
  const nlohmann::json stats = splitting.statistics();
  EXPECT_EQ(stats["scheme"], "strang");
  EXPECT_EQ(stats["sub_steps"]["a"], 2);
  EXPECT_EQ(stats["sub_steps"]["c"], 1);
  EXPECT_EQ(stats["updates"]["a"], 1);

  // A retry asked for a half step is a retry of the coupling step, scaled.
  calls.clear();
  b.retries_left_ = 1;  // asks for half of its half step
  const StepReport retry = splitting.advance(state, 1.0, 1.0);
  EXPECT_EQ(retry.status, StepReport::Status::Retry);
  EXPECT_EQ(retry.dt_retry, 0.5);
}

TEST(coupling, AnOwnIntervalIsTheProcesssProposedStepAndItsRetriesAreItsSubSteps) {
  // The slow process proposes 2.5 s; the fast one 1 s. The coupling steps
  // land on 2.5 s (1, 1, 0.5), where the slow process spans [0, 2.5]. It
  // rejects that once (Retry with half of it) and covers the span in its own
  // steps of what it asked for, without cutting the coupling step.
  std::vector<Call> calls;
  RecordingProcess fast("fast", 1.0, calls), slow("slow", 2.5, calls);
  CouplingSettings own;
  own.own_intervals = {"slow"};
  Splitting splitting({&fast, &slow}, own, 100, 1e-9);
  RockMass state;
  splitting.start(state);
  slow.retries_left_ = 1;
  for (double expected : {1.0, 1.0, 0.5}) {
    const double dt = splitting.proposed_dt(state);
    EXPECT_EQ(dt, expected);
    EXPECT_EQ(splitting.step(state, dt), 0);  // no cut of the coupling step
  }
  std::vector<Call> slow_calls;
  for (const Call& c : calls)
    if (c.process == "slow") slow_calls.push_back(c);
  EXPECT_EQ(slow_calls,
            (std::vector<Call>{{"slow", 0, 2.5}, {"slow", 0, 1.25}, {"slow", 1.25, 1.25}}));
  const nlohmann::json stats = splitting.statistics();
  EXPECT_EQ(stats["intervals"]["slow"], "own");
  EXPECT_EQ(stats["updates"]["slow"], 1);
  EXPECT_EQ(stats["sub_steps"]["slow"], 2);
  EXPECT_EQ(stats["sub_step_retries"]["slow"], 1);
  EXPECT_EQ(stats["skipped_steps"]["slow"], 2);
  EXPECT_GE(stats["seconds"]["slow"].get<double>(), 0.0);
  EXPECT_EQ(splitting.proposed_dt(state), 1.0);  // the next interval: 2.5 s again
}

TEST(coupling, TheSceneSetsTheOrderAndTheIntervalsOfTheCoupledRun) {
  // The HM stack (docs/flow.md section 7) with the flow first and sub-cycled:
  // 20 mechanics steps of 1 ms, the flow once per 5 ms.
  fissure::testing::StackParameters p;
  p.end_time = 0.02;
  Scene s = fissure::testing::hm_stack_scene(p);
  s.coupling.order = {"flow", "mechanics"};
  s.coupling.intervals["flow"] = 5e-3;
  const fissure::testing::RunResult r = fissure::testing::run_scene(s, "coupling_order");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const nlohmann::json& c = r.summary.processes["coordinator"]["coupling"];
  EXPECT_EQ(c["order"], (nlohmann::json{"flow", "mechanics"}));
  EXPECT_EQ(r.summary.steps, 20);
  EXPECT_EQ(c["updates"]["flow"], 4);
  EXPECT_EQ(c["skipped_steps"]["flow"], 16);
  EXPECT_EQ(c["updates"]["mechanics"], 20);
  EXPECT_EQ(r.summary.processes["flow"]["flow_updates"], 5);  // and the initial steady solve
}

TEST(coupling, EverySchemeRunsTheHmStack) {
  // The HM stack (docs/flow.md section 7), 20 steps of 1 ms, order
  // [mechanics, flow]. Strang: the mechanics in two half steps, the flow
  // (last) in one full step per coupling step. Iterated: the flow exchanges
  // its wall pressures, fluxes and apertures (docs/architecture.md 5), each
  // tested on its own: a step takes one pass where all are within their
  // tolerances at once, more where one still moves. (With a norm pooled
  // over the three, the pressures in Pa hid the rest: one pass per step,
  // the run Lie's to the bit.)
  fissure::testing::StackParameters p;
  p.end_time = 0.02;
  auto run = [&p](CouplingSettings::Scheme scheme, const std::string& name) {
    Scene s = fissure::testing::hm_stack_scene(p);
    s.coupling.scheme = scheme;
    return fissure::testing::run_scene(s, "coupling_scheme_" + name);
  };
  const auto lie = run(CouplingSettings::Scheme::Lie, "lie");
  const auto strang = run(CouplingSettings::Scheme::Strang, "strang");
  const auto iterated = run(CouplingSettings::Scheme::Iterated, "iterated");
  for (const auto* r : {&lie, &strang, &iterated})
    ASSERT_EQ(r->summary.status, "completed") << r->summary.message;
  const nlohmann::json& c = strang.summary.processes["coordinator"]["coupling"];
  EXPECT_EQ(c["scheme"], "strang");
  EXPECT_EQ(c["sub_steps"]["mechanics"], 2 * strang.summary.steps);
  EXPECT_EQ(c["sub_steps"]["flow"], strang.summary.steps);
  const nlohmann::json& it = iterated.summary.processes["coordinator"]["coupling"]["iteration"];
  const long passes = it["passes"], steps = iterated.summary.steps;
  EXPECT_GT(passes, steps) << it;
  EXPECT_LE(passes, 3 * steps) << it;
  EXPECT_EQ(it["not_converged_steps"], 0);
  // Every pass after a step's first had a field over its tolerance.
  long over = 0;
  for (const auto& [name, field] : it["fields"].items())
    over += field["passes_over_tolerance"].get<long>();
  EXPECT_GE(over, passes - steps) << it;
}

TEST(coupling, TheSectionIsChecked) {
  const std::string& valid = fissure::testing::kValid;  // physics: [mechanics]
  auto with = [&valid](const std::string& coupling) { return valid + "coupling:\n" + coupling; };
  EXPECT_NO_THROW(read_scene_text(with("  scheme: lie\n  order: [mechanics]\n"), "ok.yaml"));

  auto expect_one = [](const std::vector<std::string>& errors, const std::string& path,
                       const std::string& what) {
    ASSERT_EQ(errors.size(), 1u) << (errors.empty() ? "" : errors[0]);
    EXPECT_NE(errors[0].find(path), std::string::npos) << errors[0];
    EXPECT_NE(errors[0].find(what), std::string::npos) << errors[0];
  };
  EXPECT_NO_THROW(read_scene_text(with("  scheme: strang\n"), "ok.yaml"));
  const Scene iterated = read_scene_text(
      with("  scheme: iterated\n  iteration: {tolerance: 1e-8, max_iterations: 7, relaxation: "
           "fixed, omega: 0.5}\n  intervals: {mechanics: 0}\n"),
      "ok.yaml");
  EXPECT_EQ(iterated.coupling.scheme, CouplingSettings::Scheme::Iterated);
  EXPECT_EQ(iterated.coupling.iteration.tolerance, 1e-8);
  EXPECT_EQ(iterated.coupling.iteration.max_iterations, 7);
  EXPECT_EQ(iterated.coupling.iteration.relaxation, CouplingSettings::Iteration::Relaxation::Fixed);
  EXPECT_EQ(iterated.coupling.iteration.omega, 0.5);
  expect_one(fissure::testing::errors(with("  scheme: monolithic\n")), "coupling.scheme",
             "expected one of: lie, strang, iterated");
  expect_one(fissure::testing::errors(with("  iteration: {tolerance: 1e-6}\n")),
             "coupling.iteration", "expected them only with coupling.scheme: iterated");
  const std::string iterate = "  scheme: iterated\n  iteration: ";
  expect_one(fissure::testing::errors(with(iterate + "{tolerance: 0}\n")),
             "coupling.iteration.tolerance", "expected a number in (0, 1)");
  expect_one(fissure::testing::errors(with(iterate + "{tolerance: -1e-6}\n")),
             "coupling.iteration.tolerance", "expected a number in (0, 1)");
  expect_one(fissure::testing::errors(with(iterate + "{max_iterations: 0}\n")),
             "coupling.iteration.max_iterations", ">= 1");
  expect_one(fissure::testing::errors(with(iterate + "{relaxation: secant}\n")),
             "coupling.iteration.relaxation", "expected one of: aitken, fixed");
  expect_one(fissure::testing::errors(with(iterate + "{omega: 1.5}\n")), "coupling.iteration.omega",
             "expected a number in [0.05, 1]");
  expect_one(fissure::testing::errors(with(iterate + "{tolerence: 1e-6}\n")),
             "coupling.iteration.tolerence", "did you mean 'tolerance'");
  expect_one(fissure::testing::errors(with("  intervals: {mechanics: fast}\n")),
             "coupling.intervals.mechanics", "expected a time >= 0 or 'own'");
  expect_one(fissure::testing::errors(with("  intervals: {mechanics: own}\n")), "coupling",
             "expected at least one process that advances every step");
  expect_one(fissure::testing::errors(with("  order: [flow]\n")), "coupling.order[0]",
             "found 'flow', which physics does not list; expected one of: mechanics");
  expect_one(fissure::testing::errors(with("  order: [mechanics, mechanics]\n")),
             "coupling.order[1]", "a second time");
  expect_one(fissure::testing::errors(with("  intervals: {mechanics: -1 s}\n")),
             "coupling.intervals.mechanics", "expected a time >= 0");
  expect_one(fissure::testing::errors(with("  intervals: {mechanics: 1 ms}\n")), "coupling",
             "expected at least one process that advances every step");
  expect_one(fissure::testing::errors(with("  intervals: [1 ms]\n")), "coupling.intervals",
             "expected a map from process names to coupling intervals");
  expect_one(fissure::testing::errors(with("  interval: 1 ms\n")), "coupling.interval",
             "did you mean 'intervals'");
}

TEST(coupling, AQuasiStaticProcessStepsInPseudoTimeToTheUpdatesEnd) {
  // coupling.quasi_static: the process's own steps (0.25 s) all end at the
  // update's end and do not set the coupling step; with no block it is at
  // rest after one step (no block point moves).
  std::vector<Call> calls;
  RecordingProcess heat("heat", 10.0, calls), blocks("blocks", 0.25, calls);
  blocks.writes_ = {"block_kinematics"};
  CouplingSettings c = intervals({{"blocks", 20.0}});
  c.quasi_static = CouplingSettings::QuasiStatic{{"blocks"}, 1e-6, 50};
  {
    // A process that moves no blocks cannot step in pseudo-time.
    CouplingSettings on_heat = c;
    on_heat.quasi_static->processes = {"heat"};
    EXPECT_THROW(Splitting({&heat, &blocks}, on_heat, 100, 1e-9), SceneError);
  }
  Splitting lie({&heat, &blocks}, c, 100, 1e-9);
  lie.start(RockMass{});
  RockMass state;
  EXPECT_EQ(lie.proposed_dt(state), 10.0) << "the quasi-static process's 0.25 s does not count";
  blocks.retries_left_ = 1;  // its first step is cut to 0.125 s, still ending at 20 s
  for (double t : {0.0, 10.0}) ASSERT_EQ(lie.advance(state, t, 10).status, StepReport::Status::Ok);
  std::vector<Call> block_calls;
  for (const Call& call : calls)
    if (call.process == "blocks") block_calls.push_back(call);
  EXPECT_EQ(block_calls, (std::vector<Call>{{"blocks", 19.75, 0.25}, {"blocks", 19.875, 0.125}}));
  const nlohmann::json stats = lie.statistics();
  EXPECT_EQ(stats["updates"]["blocks"], 1);
  EXPECT_EQ(stats["sub_steps"]["blocks"], 1);
  EXPECT_EQ(stats["sub_step_retries"]["blocks"], 1);
  EXPECT_EQ(stats["quasi_static"]["not_at_rest"]["blocks"], 0);
  EXPECT_EQ(stats["quasi_static"]["processes"], nlohmann::json::array({"blocks"}));
}

TEST(coupling, TheQuasiStaticSectionIsChecked) {
  const std::string& valid = fissure::testing::kValid;  // physics: [mechanics]
  auto with = [&valid](const std::string& coupling) { return valid + "coupling:\n" + coupling; };
  const Scene scene = read_scene_text(
      with("  quasi_static: {processes: [mechanics], max_speed: 1e-7 m/s, max_steps: 30}\n"),
      "ok.yaml");
  ASSERT_TRUE(scene.coupling.quasi_static);
  EXPECT_EQ(scene.coupling.quasi_static->max_speed, 1e-7);
  EXPECT_EQ(scene.coupling.quasi_static->max_steps, 30);
  EXPECT_EQ(scene.coupling.quasi_static->processes, std::vector<std::string>{"mechanics"});
  auto expect_one = [](const std::vector<std::string>& errors, const std::string& what) {
    ASSERT_EQ(errors.size(), 1u) << (errors.empty() ? "" : errors[0]);
    EXPECT_NE(errors[0].find(what), std::string::npos) << errors[0];
  };
  expect_one(fissure::testing::errors(with("  quasi_static: {max_steps: 10}\n")),
             "coupling.quasi_static.processes: key is missing");
  expect_one(
      fissure::testing::errors(with("  quasi_static: {processes: [mechanics], max_speed: 0}\n")),
      "coupling.quasi_static.max_speed: found '0'; expected a velocity in (0, 10000) m/s");
  expect_one(
      fissure::testing::errors(with("  quasi_static: {processes: [mechanics], max_steps: 0}\n")),
      "coupling.quasi_static.max_steps");
  expect_one(fissure::testing::errors(with("  quasi_static: {processes: [flow]}\n")),
             "coupling.quasi_static.processes[0]: found 'flow', which physics does not list");
  expect_one(
      fissure::testing::errors(with("  quasi_static: {processes: [mechanics], max_sped: 1}\n")),
      "did you mean 'max_speed'");
}

TEST(coupling, TheFlowsOldIntervalKeyStillWorksWithAWarning) {
  const std::string scene = R"(physics: [mechanics, flow]
materials: [{name: rock, density: 2650, young_modulus: 10 GPa, poisson_ratio: 0.25}]
joints: [{name: joint, friction_angle: 30}]
blocks:
  - {name: base, vertices: [[0, 0], [4, 0], [4, 1], [0, 1]], fixed: true}
  - {name: top, vertices: [[1, 1], [3, 1], [3, 2], [1, 2]]}
mechanics: {}
flow:
  hm:
    normal_stiffness: 1 GPa/m
    coupling_interval: 5 ms
time: {end: 1}
)";
  const Scene s = read_scene_text(scene, "old.yaml");
  EXPECT_EQ(s.coupling.intervals.at("flow"), 5e-3);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("old.yaml:11:5: flow.hm.coupling_interval: is deprecated"),
            std::string::npos)
      << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("coupling: {intervals: {flow: ...}}"), std::string::npos);

  const std::vector<std::string> both =
      fissure::testing::errors(scene + "coupling: {intervals: {flow: 1 ms}}\n");
  ASSERT_EQ(both.size(), 1u);
  EXPECT_NE(both[0].find("found both flow.hm.coupling_interval and coupling.intervals.flow"),
            std::string::npos)
      << both[0];
}

TEST(coupling, NamedFieldsKeepTheirTypeAndCopyDeeply) {
  constexpr Key<std::vector<double>> kValues{"values"};
  constexpr Key<int> kWrongType{"values"};
  NamedValues fields;
  EXPECT_EQ(fields.find(kValues), nullptr);
  EXPECT_THROW(fields.get(kValues), std::logic_error);
  fields.set(kValues, std::vector<double>{1, 2});
  NamedValues copy = fields;
  copy.get(kValues).push_back(3);
  EXPECT_EQ(fields.get(kValues).size(), 2u);  // a snapshot is not changed by the run
  EXPECT_EQ(copy.get(kValues).size(), 3u);
  EXPECT_THROW(fields.find(kWrongType), std::logic_error);  // a programming error
  EXPECT_EQ(fields.names(), (std::vector<std::string>{"values"}));
}
