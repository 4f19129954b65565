// Runs under `mpirun -np 2` to the bit (issue 35, item 5; docs/continuum.md
// 3, "MPI"; docs/output.md, "Checkpoint and restart"). The scene is the
// continuum repository, whose systems the two ranks share. Two runs of it
// write the same bytes (with MUMPS they differed from the first frame, by
// up to 4e-8 Pa in stress), a 2-rank restart continues to the bits of the
// uninterrupted 2-rank run, and SIGTERM to the ranks writes a checkpoint and
// ends mpirun with exit code 2. A few steps each: about 15 s in all on 2
// quiet cores (25 s while compiling).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"
#include "tests/support/same_run.h"

extern char** environ;

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// The environment for mpirun: root allowed, and without this process's own
/// MPI variables (PETSc may have started it as a singleton): mpirun would
/// take itself for a rank.
void prepare_mpirun_environment() {
  std::vector<std::string> names;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    for (const char* prefix : {"OMPI_", "PMIX_", "OPAL_"})
      if (entry.rfind(prefix, 0) == 0) names.push_back(entry.substr(0, entry.find('=')));
  }
  for (const std::string& name : names) unsetenv(name.c_str());
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
}

/// Starts `mpirun -np 2 fissure run SCENE -q --no-plots -o OUT ARGS...` as
/// a child, its output in OUT.log; returns its process id.
pid_t start_two_ranks(const fs::path& scene, const fs::path& out,
                      const std::vector<std::string>& args) {
  const std::string log = out.string() + ".log";
  std::vector<std::string> words = {
      "mpirun", "-np",        "2",  "--oversubscribe", FISSURE_APP, "run", scene.string(),
      "-q",     "--no-plots", "-o", out.string()};
  words.insert(words.end(), args.begin(), args.end());
  const pid_t pid = fork();
  if (pid == 0) {
    prepare_mpirun_environment();
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execvp("mpirun", argv.data());
    _exit(127);
  }
  return pid;
}

/// Runs on two ranks to the end; mpirun's exit code.
int run_two_ranks(const fs::path& scene, const fs::path& out,
                  const std::vector<std::string>& args) {
  int status = 0;
  waitpid(start_two_ranks(scene, out, args), &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The processes whose parent is `parent` (mpirun's ranks), from /proc.
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> children;
  for (const fs::directory_entry& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string line;
    if (!std::getline(in, line) || line.rfind(')') == std::string::npos) continue;
    std::istringstream rest(line.substr(line.rfind(')') + 1));  // after "pid (name)"
    char state = 0;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (ppid == parent) children.push_back(std::stoi(name));
  }
  return children;
}

/// configs/continuum_repository.yaml with `output` for its output section,
/// in `dir`.
fs::path repository_scene(const fs::path& dir, const std::string& output) {
  const fs::path scene = dir / "repository.yaml";
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/continuum_repository.yaml");
  text = text.substr(0, text.find("output:\n")) + "output:\n" + output;
  std::ofstream(scene) << text;
  return scene;
}

// The default solvers on two ranks (the direct ones, rank 0 factorizing):
// 4 steps twice, the same bytes in every file but summary.json's times.
TEST(MpiRuns, TwoRanksWriteTheSameBytesTwice) {
  const fs::path dir = scratch_dir("mpi_runs");
  const fs::path scene = repository_scene(dir, "  every_steps: 2\n");
  ASSERT_EQ(run_two_ranks(scene, dir / "first", {"--max-steps", "4"}), 0)
      << file_bytes((dir / "first").string() + ".log");
  ASSERT_EQ(run_two_ranks(scene, dir / "second", {"--max-steps", "4"}), 0)
      << file_bytes((dir / "second").string() + ".log");
  for (const char* file : {"monitors.csv", "results.xdmf", "results.h5"})
    EXPECT_TRUE(file_bytes(dir / "first" / file) == file_bytes(dir / "second" / file)) << file;
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(dir / "first" / "summary.json"));
  EXPECT_EQ(summary["processes"]["continuum"]["ranks"], 2);
  EXPECT_EQ(
      without_measured_times(summary),
      without_measured_times(nlohmann::json::parse(file_bytes(dir / "second" / "summary.json"))));
}

// The repository with BDF2 on two ranks, restarted at step 4 of 8 (after a
// first leg of 6), writes the uninterrupted 2-rank run's bits.
TEST(MpiRuns, ATwoRankRestartContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("mpi_runs");
  fs::path scene = repository_scene(dir, "  every_steps: 2\n  checkpoint_steps: 4\n");
  std::string text = file_bytes(scene);
  text.replace(text.find("  time_step: 10 yr"), 18, "  time_step: 10 yr\n  time_scheme: bdf2");
  std::ofstream(scene) << text;
  ASSERT_EQ(run_two_ranks(scene, dir / "uninterrupted", {"--max-steps", "8"}), 0);
  ASSERT_EQ(run_two_ranks(scene, dir / "restarted", {"--max-steps", "6"}), 0);
  ASSERT_EQ(run_two_ranks(
                scene, dir / "restarted",
                {"--max-steps", "8", "--restart", (dir / "restarted" / "checkpoint.h5").string()}),
            0)
      << file_bytes((dir / "restarted").string() + ".log");
  expect_same_run(dir / "uninterrupted", dir / "restarted");
  const nlohmann::json summary =
      nlohmann::json::parse(file_bytes(dir / "restarted" / "summary.json"));
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 4);
}

// SIGTERM to the ranks (as a batch system signals every process of a job):
// each finishes its step, they write a checkpoint, and mpirun passes on
// their exit code 2. (A SIGTERM to mpirun itself ends Open MPI 4's mpirun
// with its own code 1: docs/output.md, "Checkpoint and restart".)
TEST(MpiRuns, SigtermToTheRanksWritesACheckpointAndExits2) {
  const fs::path dir = scratch_dir("mpi_runs");
  const fs::path scene = repository_scene(dir, "  interval: 50 yr\n  checkpoint_steps: 2\n");
  const fs::path out = dir / "stopped";
  const pid_t mpirun = start_two_ranks(scene, out, {});
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(out / "checkpoint.h5") && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const std::vector<pid_t> ranks = children_of(mpirun);
  ASSERT_EQ(ranks.size(), 2u) << file_bytes(out.string() + ".log");
  for (pid_t rank : ranks) kill(rank, SIGTERM);
  int status = 0;
  waitpid(mpirun, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "mpirun status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 2) << file_bytes(out.string() + ".log");
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(out / "summary.json"));
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_NE(summary["message"].get<std::string>().find("--restart"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "checkpoint.h5"));
}

// A jointed near field tied to a continuum on two ranks
// (configs/near_field_heated_drift.yaml, 6 steps; docs/architecture.md 5):
// the blocks, their heat and their water run on every rank and the
// continuum's systems are shared, so the ties' exchange meets the parallel
// continuum. The two ranks' monitors are the single rank's to round-off of
// the parallel assembly carried through the blocks' updates (measured: 6e-14
// m, 3e-4 Pa of 5 MPa, 2e-4 Pa of 25 MPa; 1e-8 of each column's largest
// value is a margin of about 100).
TEST(MpiRuns, ATiedNearFieldOnTwoRanksIsTheSingleRanksRun) {
  const fs::path dir = scratch_dir("mpi_runs");
  const fs::path scene = FISSURE_SOURCE_DIR "/configs/near_field_heated_drift.yaml";
  ASSERT_EQ(run_two_ranks(scene, dir / "near_field_two", {"--max-steps", "6"}), 0)
      << file_bytes((dir / "near_field_two").string() + ".log");
  const std::string log = (dir / "near_field_one.log").string();
  const std::string one = std::string(FISSURE_APP) + " run " + scene.string() +
                          " -q --no-plots --max-steps 6 -o " + (dir / "near_field_one").string() +
                          " > " + log + " 2>&1";
  ASSERT_EQ(std::system(one.c_str()), 0) << file_bytes(log);
  const nlohmann::json summary =
      nlohmann::json::parse(file_bytes(dir / "near_field_two" / "summary.json"));
  EXPECT_EQ(summary["processes"]["continuum"]["ranks"], 2);
  const std::vector<std::string> two = test::text_lines(dir / "near_field_two" / "monitors.csv");
  const std::vector<std::string> single = test::text_lines(dir / "near_field_one" / "monitors.csv");
  ASSERT_EQ(two.size(), single.size());
  ASSERT_GT(two.size(), 2u);
  EXPECT_EQ(two[0], single[0]);
  std::vector<double> largest, worst;
  for (std::size_t r = 1; r < two.size(); ++r) {
    const std::vector<double> a = test::csv_numbers(two[r]), b = test::csv_numbers(single[r]);
    ASSERT_EQ(a.size(), b.size());
    largest.resize(a.size(), 0.0);
    worst.resize(a.size(), 0.0);
    for (std::size_t c = 0; c < a.size(); ++c) {
      EXPECT_EQ(std::isnan(a[c]), std::isnan(b[c])) << "row " << r << ", column " << c;
      if (std::isnan(a[c]) || std::isnan(b[c])) continue;
      largest[c] = std::max(largest[c], std::abs(b[c]));
      worst[c] = std::max(worst[c], std::abs(a[c] - b[c]));
    }
  }
  for (std::size_t c = 0; c < worst.size(); ++c)
    EXPECT_LE(worst[c], 1e-8 * largest[c] + 1e-15) << "column " << c;
}

}  // namespace
}  // namespace fissure::testing
