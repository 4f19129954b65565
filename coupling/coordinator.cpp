#include "coupling/coordinator.h"

#include <cmath>
#include <limits>
#include <optional>

#include "core/base/errors.h"
#include "core/base/progress.h"
#include "core/io/fracture_pressure.h"
#include "core/io/monitor_writer.h"
#include "core/io/results_writer.h"
#include "core/state/monitor_values.h"
#include "coupling/process_registry.h"

namespace fissure {

namespace fs = std::filesystem;

namespace {

/// Heads are written when the flow runs with gravity (docs/flow.md 2).
HeadDefinition flow_heads(const Scene& scene) {
  if (!scene.has_physics("flow") || !scene.flow.gravity) return {};
  return {scene.flow.density, scene.gravity};
}

}  // namespace

/// The three output streams written at every output time.
class Coordinator::Output {
 public:
  Output(const Scene& scene, const fs::path& outdir)
      : monitors_(outdir / "monitors.csv", scene.monitors, scene.has_physics("mechanics"),
                  scene.has_physics("flow")) {
    if (scene.output.hdf5) results_ = std::make_unique<ResultsWriter>(outdir, flow_heads(scene));
  }

  void write(const RockMass& state, double t) {
    if (results_) results_->write_frame(state, t);
    monitors_.write_row(state, t);
    last_time_ = t;
    ++frames_;
  }

  double last_time() const { return last_time_; }
  int frames() const { return frames_; }

 private:
  std::unique_ptr<ResultsWriter> results_;
  MonitorWriter monitors_;
  double last_time_ = -std::numeric_limits<double>::infinity();
  int frames_ = 0;
};

Coordinator::Coordinator(const Scene& scene, RunOptions options)
    : scene_(scene), options_(std::move(options)), state_(RockMass::from_scene(scene)) {}

Coordinator::~Coordinator() = default;

double Coordinator::next_step_size(double next_output) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& p : processes_) dt = std::min(dt, p->proposed_dt(state_));
  const double target = std::min(scene_.time.end_time, next_output);
  const double remaining = target - state_.time;
  // Land exactly on output and end times; never leave a sliver step behind.
  if (dt >= remaining - 1e-6 * dt) dt = remaining;
  return dt;
}

void Coordinator::advance_one_step(double dt) {
  // With several processes, a late retry must undo the earlier ones' work.
  std::optional<RockMass> snapshot;
  if (processes_.size() > 1) snapshot = state_;
  const double t = state_.time;
  for (;;) {
    StepReport report;
    for (auto& p : processes_) {
      report = p->advance(state_, t, dt);
      if (report.status == StepReport::Status::Retry) break;
    }
    if (report.status == StepReport::Status::Ok) return;
    ++cuts_;
    if (snapshot) state_ = *snapshot;
    FISSURE_CHECK(report.dt_retry < dt && report.dt_retry >= scene_.time.min_step, DivergenceError,
                  "the step at t = " << t << " s cannot be completed: " << report.reason
                                     << " (the time step would be cut to " << report.dt_retry
                                     << " s, below time.min_step = " << scene_.time.min_step
                                     << " s)");
    dt = report.dt_retry;
  }
}

bool Coordinator::output_due(long step, double next_output) const {
  if (scene_.output.interval > 0) return state_.time >= next_output;
  return scene_.output.every_steps > 0 && step % scene_.output.every_steps == 0;
}

RunSummary Coordinator::run() {
  RunSummary summary;
  summary.scene = scene_.name;

  // 1. Output folder; a first summary marks the run as started.
  fs::create_directories(options_.outdir);
  const fs::path summary_file = options_.outdir / "summary.json";
  write_summary(summary_file, summary);
  Output output(scene_, options_.outdir);
  Progress progress(scene_.time.end_time, options_.progress_bar, options_.quiet);

  try {
    // 2. Only the processes the scene activates are built.
    processes_ = create_processes(scene_);
    for (auto& p : processes_) p->initialize(state_);

    // 3. Initial frame.
    output.write(state_, state_.time);
    const double interval = scene_.output.interval;
    double next_output =
        interval > 0 ? interval : std::numeric_limits<double>::infinity();

    // 4. Time loop.
    const double end = scene_.time.end_time;
    while (state_.time < end * (1 - 1e-12)) {
      if (scene_.time.max_steps >= 0 && steps_ >= scene_.time.max_steps) break;
      const double dt = next_step_size(next_output);
      advance_one_step(dt);
      ++steps_;
      if (output_due(steps_, next_output)) {
        output.write(state_, state_.time);
        while (interval > 0 && next_output <= state_.time * (1 + 1e-12)) next_output += interval;
      }
      progress.update(steps_, state_.time);
    }
    if (state_.time >= end * (1 - 1e-12)) {
      summary.status = "completed";
    } else {
      summary.status = "max_steps";
      summary.message = "stopped after time.max_steps = " + std::to_string(scene_.time.max_steps) +
                        " steps before time.end";
    }
  } catch (const DivergenceError& e) {
    summary.status = "diverged";
    summary.message = e.what();
  } catch (const std::exception& e) {
    summary.status = "failed";
    summary.message = e.what();
  }
  progress.finish(steps_, state_.time);

  // 5. Final frame (the last accepted state) and the summary.
  try {
    if (output.last_time() < state_.time) output.write(state_, state_.time);
  } catch (const std::exception& e) {
    summary.message += std::string(summary.message.empty() ? "" : "; ") +
                       "could not write the final frame: " + e.what();
  }
  summary.steps = steps_;
  summary.simulated_time = state_.time;
  summary.wall_seconds = progress.wall_seconds();
  summary.output_frames = output.frames();
  summary.processes["coordinator"] = {{"time_step_cuts", cuts_}, {"steps", steps_}};
  for (const auto& p : processes_) {
    nlohmann::json stats = p->statistics();
    for (Field f : p->reads()) stats["reads"].push_back(to_string(f));
    for (Field f : p->writes()) stats["writes"].push_back(to_string(f));
    summary.processes[p->name()] = stats;
    const nlohmann::json energy = p->energy(state_);
    for (const auto& [key, value] : energy.items()) summary.energy[key] = value;
  }
  for (std::size_t m = 0; m < scene_.monitors.size(); ++m) {
    const MonitorValues v = evaluate_monitor(state_, static_cast<int>(m));
    summary.monitors[scene_.monitors[m].name] = {
        {"x", v.position.x()},      {"y", v.position.y()},      {"ux", v.displacement.x()},
        {"uy", v.displacement.y()}, {"vx", v.velocity.x()},     {"vy", v.velocity.y()},
        {"sxx", v.stress(0)},       {"syy", v.stress(1)},       {"sxy", v.stress(2)}};
    if (scene_.has_physics("flow"))
      summary.monitors[scene_.monitors[m].name]["p"] =
          fracture_pressure_at(state_, state_.points[m].current);
  }
  write_summary(summary_file, summary);
  return summary;
}

}  // namespace fissure
