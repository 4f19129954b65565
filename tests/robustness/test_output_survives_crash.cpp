// Nothing is lost (docs/output.md): a run that dies without any clean-up
// (_exit, abort, SIGKILL) leaves results.h5, results.xdmf, monitors.csv and
// summary.json that describe every frame written before it died and that open
// cleanly. A child process writes and dies; the parent reads what is left.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "core/io/monitor_writer.h"
#include "core/io/results_writer.h"
#include "core/io/summary_writer.h"
#include "tests/support/output_parts.h"
#include "tests/support/output_test_state.h"
#include "tests/support/results_file_reader.h"

namespace fs = std::filesystem;
using namespace fissure;
using namespace fissure::test;

namespace {

enum class Death { Exit, Abort, Kill };

fs::path fresh_output_dir(const std::string& name) {
  const fs::path dir =
      fs::path(FISSURE_BINARY_DIR) / "test-output" / "output_survives_crash" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Child side: writes frames 0 .. n-1 (or forever when n < 0) and dies
/// without destroying anything. Never returns.
[[noreturn]] void write_and_die(const fs::path& dir, int n, Death how) {
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);  // abort() must not leave a core file behind
  try {
    RunSummary summary;
    summary.scene = "crash";
    write_summary(dir / "summary.json", summary);
    auto* parts = new OutputParts;  // deliberately never deleted
    auto* results = new ResultsWriter(dir, parts->results());
    auto* monitors =
        new MonitorWriter(dir / "monitors.csv", output_test_monitors(), parts->monitors(true));
    RockMass s = output_test_state();
    for (int k = 0; n < 0 || k < n; ++k) {
      set_output_test_frame(s, k);
      results->write_frame(s, s.time);
      monitors->write_row(s, s.time);
    }
  } catch (...) {
    _exit(3);
  }
  switch (how) {
    case Death::Exit:
      _exit(1);
    case Death::Abort:
      std::abort();
    case Death::Kill:
      raise(SIGKILL);
  }
  _exit(4);
}

/// Waits until the writer's index lists at least `frames` frames; false
/// after `timeout` (the child then writes too slowly to be of use).
bool wait_for_frames(const fs::path& dir, std::size_t frames, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    // The index is replaced atomically (rename): it is never read half-written.
    if (fs::exists(dir / "results.xdmf") &&
        xdmf_times(read_text(dir / "results.xdmf")).size() >= frames)
      return true;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

std::string frame_group(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%06d", k);
  return name;
}

/// The frame group holds exactly frame k of the test motion.
void expect_frame(const H5Reader& h5, int k) {
  SCOPED_TRACE("frame " + std::to_string(k));
  const std::string g = frame_group(k);
  EXPECT_EQ(h5.double_attribute(g, "time"), frame_time(k));
  RockMass s = output_test_state();
  set_output_test_frame(s, k);
  std::vector<double> x, u;
  for (const Block& b : s.blocks)
    for (std::size_t v = 0; v < b.polygon.vertices.size(); ++v) {
      x.insert(x.end(), {b.polygon.vertices[v].x(), b.polygon.vertices[v].y()});
      const Vec2 d = b.polygon.vertices[v] - b.initial_vertices[v];
      u.insert(u.end(), {d.x(), d.y(), 0.0});
    }
  EXPECT_EQ(h5.doubles(g + "/vertices"), x);
  EXPECT_EQ(h5.doubles(g + "/displacement"), u);
  EXPECT_EQ(h5.doubles(g + "/sxx").front(), -1e6 - k);
  if (k % 4 == 0) {
    EXPECT_FALSE(h5.exists(g + "/contacts"));
  } else {
    EXPECT_EQ(h5.ints(g + "/contacts/state").size(), static_cast<std::size_t>(k % 4));
    EXPECT_EQ(h5.doubles(g + "/contacts/gap").front(), -1e-4 * k);
  }
}

const char* name(Death how) {
  return how == Death::Exit ? "Exit" : how == Death::Abort ? "Abort" : "Kill";
}

// Readable test names in ctest ("... /Abort") instead of a byte dump.
[[maybe_unused]] void PrintTo(Death how, std::ostream* os) {
  *os << name(how);
}

class output_survives_crash : public ::testing::TestWithParam<Death> {};

}  // namespace

TEST_P(output_survives_crash, DeathAfterThreeFrames) {
  const Death how = GetParam();
  const fs::path dir = fresh_output_dir(name(how));
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) write_and_die(dir, 3, how);

  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  if (how == Death::Exit) {
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << "child status " << status;
  } else {
    ASSERT_TRUE(WIFSIGNALED(status)) << "child status " << status;
    EXPECT_EQ(WTERMSIG(status), how == Death::Abort ? SIGABRT : SIGKILL);
  }

  // results.h5 opens and holds the three frames, exactly.
  H5Reader h5(dir / "results.h5");
  EXPECT_EQ(h5.members("/frames"), (std::vector<std::string>{"000000", "000001", "000002"}));
  EXPECT_EQ(h5.ints("/mesh/block_vertex_offsets"), (std::vector<int>{0, 4, 10, 18}));
  for (int k = 0; k < 3; ++k) expect_frame(h5, k);

  // results.xdmf lists the same three time steps, and nothing it names is missing.
  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_TRUE(xml_tags_balanced(xml));
  EXPECT_EQ(xdmf_times(xml), (std::vector<double>{0, 0.25, 0.5}));
  expect_xdmf_refs_match(xml, h5);
  EXPECT_FALSE(fs::exists(dir / "results.xdmf.tmp"));

  // monitors.csv has its header and the three rows; summary.json is valid.
  const std::string csv = read_text(dir / "monitors.csv");
  EXPECT_EQ(count_occurrences(csv, "\n"), 4);
  EXPECT_EQ(csv.substr(csv.rfind('\n', csv.size() - 2) + 1, 4), "0.5,");
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "summary.json"))["status"], "running");
}

INSTANTIATE_TEST_SUITE_P(Death, output_survives_crash,
                         ::testing::Values(Death::Exit, Death::Abort, Death::Kill),
                         [](const auto& info) { return std::string(name(info.param)); });

// A kill can land anywhere, including half-way through a frame, an HDF5
// flush or the rewrite of the index. Whatever the index lists must then be
// complete. 12 kills by default; FISSURE_KILL_TRIALS=2000 makes it a stress
// test (kills spread at random over the first 0.4 s of each run).
TEST(output_survives_crash, KillAtArbitraryMomentsKeepsIndexedFramesComplete) {
  const char* env = std::getenv("FISSURE_KILL_TRIALS");
  const int trials = env ? std::max(1, std::atoi(env)) : 12;
  std::mt19937 rng(20240611);
  int total_frames = 0;
  for (int trial = 0; trial < trials; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const fs::path dir = fresh_output_dir("arbitrary");
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) write_and_die(dir, -1, Death::Kill);
    // By default spread over the child's life by its progress, not by the
    // clock (a busy machine writes fewer frames in the same time): trial t
    // waits until t frames are listed, then kills at a moment within the
    // next frame's writing; trial 0 kills before the first frame. In stress
    // mode at random times.
    if (env) {
      std::this_thread::sleep_for(
          std::chrono::microseconds(std::uniform_int_distribution<int>(0, 400000)(rng)));
    } else {
      const bool progressing = wait_for_frames(dir, trial, std::chrono::seconds(60));
      if (!progressing) kill(pid, SIGKILL);
      ASSERT_TRUE(progressing) << "the writer listed fewer than " << trial << " frames in 60 s";
      const int within_us = trial == 0 ? 300 : std::uniform_int_distribution<int>(0, 3000)(rng);
      std::this_thread::sleep_for(std::chrono::microseconds(within_us));
    }
    kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child status " << status;

    if (!fs::exists(dir / "results.xdmf")) continue;  // died before the first index
    const std::string xml = read_text(dir / "results.xdmf");
    ASSERT_TRUE(xml_tags_balanced(xml));
    const std::vector<double> times = xdmf_times(xml);
    if (times.empty()) continue;
    H5Reader h5(dir / "results.h5");
    for (std::size_t k = 0; k < times.size(); ++k) {
      ASSERT_EQ(times[k], frame_time(static_cast<int>(k)));
      expect_frame(h5, static_cast<int>(k));
    }
    expect_xdmf_refs_match(xml, h5);
    total_frames += static_cast<int>(times.size());
  }
  // The trials must actually have killed runs that had written frames.
  EXPECT_GT(total_frames, trials);
}
