#include "coupling/coordinator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/base/interrupt.h"
#include "core/base/memory_budget.h"
#include "core/base/progress.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/io/monitor_writer.h"
#include "core/io/point_markers.h"
#include "core/io/results_writer.h"
#include "core/parallel/mpi_world.h"
#include "core/state/monitor_values.h"
#include "core/state/rock_mass_checkpoint.h"
#include "coupling/checkpoint_file.h"
#include "coupling/process_registry.h"

namespace fissure {

namespace fs = std::filesystem;

namespace {

/// time.max_steps ended the initial stage: the run stops there, as it would
/// in the time loop (status max_steps).
struct StageStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace

/// The three output streams written at every output time, from what the
/// processes (and the shared fields no process owns) declare. A restarted
/// run continues the files of the checkpointed one.
class Coordinator::Output {
 public:
  /// `resume` (with the state the first frame was written from): the
  /// checkpoint's output section.
  Output(const Scene& scene, const fs::path& outdir,
         const std::vector<std::unique_ptr<Process>>& processes,
         const std::vector<std::unique_ptr<ResultsPart>>& shared,
         CheckpointReader* resume = nullptr, const RockMass* first_state = nullptr)
      : monitors_(outdir / "monitors.csv", scene.monitors, monitor_sources(processes), nullptr,
                  resume ? std::optional(monitor_bytes(*resume)) : std::nullopt),
        monitor_markers_(scene.monitors) {
    if (resume) {
      (*resume)("last_time", last_time_);
      (*resume)("frames", frames_);
    }
    if (!scene.output.hdf5) return;
    std::vector<ResultsPart*> parts = {&monitor_markers_};
    for (const auto& p : processes)
      if (ResultsPart* part = p->results()) parts.push_back(part);
    for (const auto& part : shared) parts.push_back(part.get());
    if (resume) {
      CheckpointReader results = resume->section("results");
      results_ =
          std::make_unique<ResultsWriter>(outdir, parts, results, *first_state, scene.time.unit);
    } else {
      results_ = std::make_unique<ResultsWriter>(outdir, parts, scene.time.unit);
    }
  }

  static std::vector<const MonitorSource*> monitor_sources(
      const std::vector<std::unique_ptr<Process>>& processes) {
    std::vector<const MonitorSource*> sources;
    for (const auto& p : processes)
      if (const MonitorSource* s = p->monitors()) sources.push_back(s);
    return sources;
  }

  void write(const RockMass& state, double t) {
    if (results_) results_->write_frame(state, t);
    monitors_.write_row(state, t);
    last_time_ = t;
    ++frames_;
  }

  /// Where each file stands, for a checkpoint.
  void save(CheckpointWriter& out) const {
    out("monitors_bytes", monitors_.bytes());
    out("last_time", last_time_);
    out("frames", frames_);
    if (results_) {
      CheckpointWriter results = out.section("results");
      results_->save(results);
    }
  }

  double last_time() const { return last_time_; }
  int frames() const { return frames_; }

 private:
  static std::uintmax_t monitor_bytes(CheckpointReader& resume) {
    std::uintmax_t bytes = 0;
    resume("monitors_bytes", bytes);
    return static_cast<std::uintmax_t>(bytes);
  }

  std::unique_ptr<ResultsWriter> results_;
  MonitorWriter monitors_;
  MonitorMarkers monitor_markers_;  ///< where the monitors are, for the pictures
  double last_time_ = -std::numeric_limits<double>::infinity();
  int frames_ = 0;
};

Coordinator::Coordinator(const Scene& scene, RunOptions options)
    : scene_(scene), options_(std::move(options)), state_(RockMass::from_scene(scene)) {}

Coordinator::~Coordinator() = default;

void Coordinator::check() {
  start();
  for (auto& p : processes_) p->initialize(state_);
}

void Coordinator::start() {
  processes_ = create_processes(scene_);
  std::vector<Process*> order;
  for (const auto& p : processes_) order.push_back(p.get());
  splitting_ = std::make_unique<Splitting>(order, scene_.coupling, scene_.time.end_time,
                                           scene_.time.min_step);
  shared_results_ = shared_results_parts();
}

void Coordinator::begin(std::unique_ptr<Output>& output, double& next_output,
                        CheckpointFile* checkpoint) {
  const double interval = scene_.output.interval;
  if (options_.restart.empty()) {
    splitting_->start(state_);
    // 3. Initial frame.
    if (options_.write_files) {
      output = std::make_unique<Output>(scene_, options_.outdir, processes_, shared_results_);
      output->write(state_, state_.time);
    }
    next_output = interval > 0 ? interval : std::numeric_limits<double>::infinity();
    return;
  }
  // 3'. Restart: the checkpoint's state over the initialized one, then
  // every process's, then the files continued where the checkpoint was.
  CheckpointReader root = checkpoint->root();
  RockMass first_state = state_;  // what the first frame was written from
  checkpoint_run(root, next_output);
  // After an initial stage the first frame held the settled blocks, which
  // are the initial vertices of the checkpointed state.
  if (scene_.coupling.initial_equilibrium)
    for (std::size_t b = 0; b < first_state.blocks.size(); ++b)
      first_state.blocks[b].initial_vertices = first_state.blocks[b].polygon.vertices =
          state_.blocks[b].initial_vertices;
  CheckpointReader processes = root.section("processes");
  for (auto& p : processes_) {
    CheckpointReader section = processes.section(p->name());
    p->restore(section, state_);
  }
  CheckpointReader files = root.section("output");
  if (options_.write_files)
    output = std::make_unique<Output>(scene_, options_.outdir, processes_, shared_results_, &files,
                                      &first_state);
  last_checkpoint_step_ = restarted_at_ = steps_;
}

template <class Archive>
void Coordinator::checkpoint_run(Archive& root, double& next_output) {
  auto coordinator = root.section("coordinator");
  coordinator("steps", steps_);
  coordinator("cuts", cuts_);
  coordinator("checkpoints", checkpoints_);
  coordinator("next_output", next_output);
  // The initial stage's figures (summary.json): a restart does not repeat it.
  std::string stage = initial_equilibrium_.is_null() ? "" : initial_equilibrium_.dump();
  coordinator("initial_equilibrium", stage);
  if (!stage.empty()) initial_equilibrium_ = nlohmann::json::parse(stage);
  auto state = root.section("state");
  checkpoint(state, state_);
  auto coupling = root.section("coupling");
  splitting_->checkpoint(coupling);
}

void Coordinator::write_checkpoint(const Output& output, double next_output) {
  const Stopwatch clock;
  ++checkpoints_;
  write_checkpoint_file(options_.outdir / "checkpoint.h5", scene_, [&](CheckpointWriter& root) {
    checkpoint_run(root, next_output);
    CheckpointWriter processes = root.section("processes");
    for (const auto& p : processes_) {
      CheckpointWriter section = processes.section(p->name());
      p->save(section, state_);
    }
    CheckpointWriter files = root.section("output");
    output.save(files);
  });
  checkpoint_seconds_ += clock.seconds();
  last_checkpoint_step_ = steps_;
  last_checkpoint_wall_ = wall_;
}

bool Coordinator::checkpoint_due() const {
  const OutputControls& o = scene_.output;
  return (o.checkpoint_steps > 0 && steps_ - last_checkpoint_step_ >= o.checkpoint_steps) ||
         (o.checkpoint_wall_time > 0 && wall_ - last_checkpoint_wall_ >= o.checkpoint_wall_time);
}

double Coordinator::next_step_size(double next_output) const {
  double dt = splitting_->proposed_dt(state_);
  const double target = std::min(scene_.time.end_time, next_output);
  const double remaining = target - state_.time;
  // Land exactly on output and end times; never leave a sliver step behind.
  if (dt >= remaining - 1e-6 * dt) dt = remaining;
  return dt;
}

bool Coordinator::settle() {
  const CouplingSettings::InitialEquilibrium& stage = *scene_.coupling.initial_equilibrium;
  // The stage's processes advance alone; the others stay as they started
  // (the shared fields they wrote, loads on the blocks say, act on the
  // stage unchanged).
  std::vector<Process*> alone, others;
  for (const auto& p : processes_) {
    const bool listed = std::find(stage.processes.begin(), stage.processes.end(), p->name()) !=
                        stage.processes.end();
    if (listed || (stage.processes.empty() && alone.empty()))
      alone.push_back(p.get());
    else
      others.push_back(p.get());
  }
  Splitting splitting(alone, CouplingSettings{}, stage.max_time, scene_.time.min_step);
  splitting.start(state_);
  long steps = 0;
  double speed = std::numeric_limits<double>::infinity();
  const long max_steps = scene_.time.max_steps;
  while (state_.time < stage.max_time * (1 - 1e-12)) {
    if (max_steps >= 0 && steps >= max_steps) break;
    const double dt = std::min(splitting.proposed_dt(state_), stage.max_time - state_.time);
    cuts_ += splitting.step(state_, dt);
    ++steps;
    speed = fastest_block_point(state_);
    if (speed <= stage.max_speed) break;
  }
  nlohmann::json names = nlohmann::json::array();
  for (const Process* p : alone) names.push_back(p->name());
  initial_equilibrium_ = {{"processes", names},
                          {"steps", steps},
                          {"simulated_time", state_.time},
                          {"fastest_point", speed},
                          {"max_speed", stage.max_speed}};
  if (speed > stage.max_speed && max_steps >= 0 && steps >= max_steps) return false;
  FISSURE_CHECK(speed <= stage.max_speed, DivergenceError,
                "initial equilibrium not reached in coupling.initial_equilibrium.max_time = "
                    << stage.max_time << " s (" << steps << " steps): a block point still moves at "
                    << speed << " m/s, more than max_speed = " << stage.max_speed << " m/s");
  // The settled state is the start of the coupled run: the other processes
  // start again from it (docs/architecture.md 2), then the displacements are
  // reset (a process that follows the blocks from their initial vertices
  // copies them when it starts).
  state_.time = 0;
  for (Process* p : others) p->initialize(state_);
  for (Block& b : state_.blocks) {
    b.initial_vertices = b.polygon.vertices;
    b.velocity.setZero();
    b.strain.setZero();
    b.rotation = 0;
  }
  for (MaterialPoint& m : state_.points) m.initial = m.current;
  return true;
}

bool Coordinator::output_due(long step, double next_output) const {
  if (scene_.output.interval > 0) return state_.time >= next_output;
  return scene_.output.every_steps > 0 && step % scene_.output.every_steps == 0;
}

const Process* Coordinator::process(std::string_view name) const {
  for (const auto& p : processes_)
    if (p->name() == name) return p.get();
  return nullptr;
}

RunSummary Coordinator::run() {
  RunSummary summary;
  summary.scene = scene_.name;
  summary.scene_file = recorded_file_path(scene_.source);
  summary.time_unit = scene_.time.unit;

  // 1. A restart's checkpoint, every byte of it checked: a refused one
  // leaves the output folder as it is (not even summary.json is written).
  const bool restarting = !options_.restart.empty();
  std::unique_ptr<CheckpointFile> checkpoint;
  if (restarting) {
    try {
      checkpoint = std::make_unique<CheckpointFile>(options_.restart, scene_);
    } catch (const IoError& e) {
      throw RestartRefused(e.what());
    }
  }

  // Output folder; a first summary marks a fresh run as started.
  const fs::path summary_file = options_.outdir / "summary.json";
  if (options_.write_files && !restarting) {
    fs::create_directories(options_.outdir);
    write_summary(summary_file, summary);
  }

  // 2. Only the processes the scene activates are built (in the order they
  // advance); they allocate nothing before initialize.
  std::string failure;
  try {
    start();
  } catch (const std::exception& e) {
    failure = e.what();
    processes_.clear();
  }
  std::unique_ptr<Output> output;
  Progress progress(scene_.time.end_time, options_.progress_bar, options_.quiet);
  const InterruptGuard interrupts;
  const Stopwatch wall;

  bool begun = false;  // the first frame written, or the restarted files continued
  try {
    if (!failure.empty()) throw Error(failure);
    for (auto& p : processes_) p->initialize(state_);
    // A restart continues after the stage: the checkpoint holds its state.
    if (scene_.coupling.initial_equilibrium && options_.restart.empty() && !settle())
      throw StageStopped("stopped after time.max_steps = " + std::to_string(scene_.time.max_steps) +
                         " steps of the initial stage (coupling.initial_equilibrium), before the "
                         "blocks came to rest");
    const double interval = scene_.output.interval;
    double next_output = std::numeric_limits<double>::infinity();
    begin(output, next_output, checkpoint.get());
    begun = true;
    if (restarting && options_.write_files) write_summary(summary_file, summary);

    // 4. Time loop.
    const double end = scene_.time.end_time;
    while (state_.time < end * (1 - 1e-12)) {
      if (scene_.time.max_steps >= 0 && steps_ >= scene_.time.max_steps) break;
      const double dt = next_step_size(next_output);
      cuts_ += splitting_->step(state_, dt);
      ++steps_;
      if (output_due(steps_, next_output)) {
        if (output) output->write(state_, state_.time);
        while (interval > 0 && next_output <= state_.time * (1 + 1e-12)) next_output += interval;
      }
      progress.update(steps_, state_.time);
      wall_ = wall.seconds();
      // Every rank stops at the same step (mpirun passes a signal on to
      // each rank, not at the same instant).
      if (const int signal = parallel::all_max(InterruptGuard::signal())) {
        if (output) write_checkpoint(*output, next_output);
        summary.status = "interrupted";
        summary.message = fmt::format(
            "stopped by {} at t = {:g} s; continue with: fissure run {} -o {} --restart {}",
            InterruptGuard::name(signal), state_.time, scene_.source.string(),
            options_.outdir.string(), (options_.outdir / "checkpoint.h5").string());
        break;
      }
      if (output && checkpoint_due()) write_checkpoint(*output, next_output);
    }
    if (summary.status != "interrupted") {
      const bool completed = state_.time >= end * (1 - 1e-12);
      summary.status = completed ? "completed" : "max_steps";
      if (!completed)
        summary.message =
            "stopped after time.max_steps = " + std::to_string(scene_.time.max_steps) +
            " steps before time.end";
    }
  } catch (const StageStopped& e) {
    summary.status = "max_steps";
    summary.message = e.what();
  } catch (const DivergenceError& e) {
    summary.status = "diverged";
    summary.message = e.what();
  } catch (const CouplingOrderError& e) {
    // Located where the order is written (the default order has no place).
    const SourceLocation& at = scene_.coupling.order_location;
    summary.status = "failed";
    summary.message =
        at.line > 0 ? fmt::format("{}:{}:{}: {}", at.file, at.line, at.column, e.what()) : e.what();
  } catch (const std::bad_alloc&) {
    summary.status = "failed";
    summary.message = fmt::format(
        "out of memory at step {}, t = {:g} s: the run needed more than the machine gave it "
        "({} were available at the start); expected a smaller scene, or more memory",
        steps_ + 1, state_.time, format_bytes(memory_budget()));
  } catch (const std::exception& e) {
    summary.status = "failed";
    summary.message = e.what();
  }
  // A restart that could not continue its files (its output folder is not
  // the checkpointed run's, or the checkpoint's state does not fit the
  // processes) has touched nothing, and leaves it so.
  if (restarting && !begun) throw RestartRefused(summary.message);
  if (!output && options_.write_files) {
    try {
      output = std::make_unique<Output>(scene_, options_.outdir, processes_, shared_results_);
    } catch (const std::exception& e) {
      summary.message += std::string("; ") + e.what();
    }
  }
  progress.finish(steps_, state_.time);

  // 5. Final frame (the last accepted state) and the summary.
  try {
    if (output && output->last_time() < state_.time) output->write(state_, state_.time);
  } catch (const std::exception& e) {
    summary.message += std::string(summary.message.empty() ? "" : "; ") +
                       "could not write the final frame: " + e.what();
  }
  summary.steps = steps_;
  summary.simulated_time = state_.time;
  summary.wall_seconds = progress.wall_seconds();
  summary.output_frames = output ? output->frames() : 0;
  summarize(summary);
  if (options_.write_files) write_summary(summary_file, summary);
  return summary;
}

void Coordinator::summarize(RunSummary& summary) const {
  nlohmann::json coordinator = {{"time_step_cuts", cuts_}, {"steps", steps_}};
  coordinator["checkpoints"] = {{"written", checkpoints_}, {"seconds", checkpoint_seconds_}};
  if (!options_.restart.empty())
    coordinator["checkpoints"]["restarted"] = {{"from", options_.restart.string()},
                                               {"at_step", restarted_at_}};
  if (splitting_) coordinator["coupling"] = splitting_->statistics();
  if (!initial_equilibrium_.is_null()) coordinator["initial_equilibrium"] = initial_equilibrium_;
  summary.processes["coordinator"] = coordinator;
  for (const auto& p : processes_) {
    nlohmann::json stats = p->statistics();
    for (const std::string& f : p->reads()) stats["reads"].push_back(f);
    for (const std::string& f : p->writes()) stats["writes"].push_back(f);
    summary.processes[p->name()] = stats;
    const nlohmann::json energy = p->energy(state_);
    for (const auto& [key, value] : energy.items()) summary.energy[key] = value;
  }
  // Final monitor values: the columns of monitors.csv.
  const MonitorLayout layout(Output::monitor_sources(processes_));
  for (const MonitorLayout::Column& c : layout.columns())
    if (c.brief) summary.brief_monitor_columns.push_back(c.name);
  for (std::size_t m = 0; m < scene_.monitors.size(); ++m) {
    const std::vector<double> values = layout.values(state_, static_cast<int>(m));
    nlohmann::json& entry = summary.monitors[scene_.monitors[m].name];
    entry = nlohmann::json::object();
    // A column without a value at this monitor (a block's velocity at a
    // point of the continuum, a pressure off the network) is left out.
    for (std::size_t c = 0; c < layout.columns().size(); ++c)
      if (!std::isnan(values[c])) entry[layout.columns()[c].name] = values[c];
  }
}

}  // namespace fissure
