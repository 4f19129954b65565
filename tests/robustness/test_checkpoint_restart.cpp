// Checkpoint and restart (issue 22, item 6; docs/output.md "Checkpoint and
// restart"). A run killed with SIGKILL, or stopped by SIGTERM, and continued
// with `fissure run --restart` from its last checkpoint writes the same
// monitors.csv and results.xdmf bytes, the same results.h5 values and the
// same summary.json (but for measured times and the checkpoint counts) as
// a run that was never interrupted. The scenes exercise the state that is
// hardest to carry over: a 420-brick dynamic wall above the `auto` solver's
// direct threshold (the reused factorization with its low-rank corrections,
// the cost model's choice between it and pcg, contacts with shear-force
// history), and the transient HM injection (the flow's pressures, storage
// volumes and sub-cycling). The kill is triggered by progress (the first
// checkpoint on disk), not by the clock. Refused checkpoints:
// test_checkpoint_integrity.cpp.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/near_field_scenes.h"
#include "tests/support/run_scene.h"
#include "tests/support/same_run.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// Runs `fissure run SCENE -q --no-plots -o OUT [extra...]` and returns its exit code.
int run(const fs::path& scene, const fs::path& out, const std::vector<std::string>& extra = {}) {
  std::string command = std::string("\"") + FISSURE_APP + "\" run \"" + scene.string() +
                        "\" -q --no-plots -o \"" + out.string() + "\"";
  for (const std::string& e : extra) command += " " + e;
  command += " > \"" + out.string() + ".log\" 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Starts `fissure run` as a child, waits until it has written its first
/// checkpoint, sends it `signal` and returns how it ended.
int run_until_checkpoint_then(int signal, const fs::path& scene, const fs::path& out,
                              long max_steps) {
  fs::create_directories(out);
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string steps = std::to_string(max_steps);
    const std::string log = out.string() + ".log";
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    execl(FISSURE_APP, FISSURE_APP, "run", scene.c_str(), "-q", "--no-plots", "-o", out.c_str(),
          "--max-steps", steps.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(out / "checkpoint.h5") && std::chrono::steady_clock::now() < give_up) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return status;  // ended on its own
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, signal);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// The 420-brick dynamic wall with a frame every 10 steps and a checkpoint
/// every 20.
fs::path wall_scene(const fs::path& dir) {
  const fs::path scene = dir / "wall_420.yaml";
  std::string text = generated_brick_wall(scene.string(), 20, 20);
  const std::string output = "output:\n";
  text = text.substr(0, text.find(output)) + "output:\n  every_steps: 10\n  checkpoint_steps: 20\n";
  std::ofstream(scene) << text;
  return scene;
}

TEST(CheckpointRestart, AKilledWallContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = wall_scene(dir);
  ASSERT_EQ(run(scene, dir / "uninterrupted", {"--max-steps 160"}), 0);

  const int status = run_until_checkpoint_then(SIGKILL, scene, dir / "killed", 160);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child status " << status;
  ASSERT_EQ(
      run(scene, dir / "killed",
          {"--max-steps 160", "--restart \"" + (dir / "killed" / "checkpoint.h5").string() + "\""}),
      0)
      << file_bytes((dir / "killed").string() + ".log");
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(dir / "killed" / "summary.json"));
  EXPECT_GT(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"].get<long>(),
            0);
  // Both back ends of `auto` were in use after the restart too.
  const nlohmann::json& solver = summary["processes"]["mechanics"]["linear_solver"];
  EXPECT_GT(solver["reused_factorization"]["corrected_solves"].get<long>(), 0);
  expect_same_run(dir / "uninterrupted", dir / "killed");
}

TEST(CheckpointRestart, SigtermWritesACheckpointAndStopsCleanly) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = wall_scene(dir);
  ASSERT_EQ(run(scene, dir / "uninterrupted", {"--max-steps 100"}), 0);

  const int status = run_until_checkpoint_then(SIGTERM, scene, dir / "stopped", 100);
  ASSERT_TRUE(WIFEXITED(status)) << "child status " << status;
  const nlohmann::json stopped =
      nlohmann::json::parse(file_bytes(dir / "stopped" / "summary.json"));
  if (WEXITSTATUS(status) == 2) {  // else it ended before the signal came
    EXPECT_EQ(stopped["status"], "interrupted");
    EXPECT_NE(stopped["message"].get<std::string>().find("--restart"), std::string::npos);
  }
  ASSERT_EQ(run(scene, dir / "stopped",
                {"--max-steps 100",
                 "--restart \"" + (dir / "stopped" / "checkpoint.h5").string() + "\""}),
            0);
  expect_same_run(dir / "uninterrupted", dir / "stopped");
}

/// Runs `scene` uninterrupted for `steps` steps into dir/uninterrupted, and
/// into dir/restarted for `first_leg` steps and then restarted from its last
/// checkpoint to `steps`; the two must match (expect_same_run).
/// `text` with its output section replaced: a frame every 2 steps and a
/// checkpoint every 4.
std::string with_frames_and_checkpoints(const std::string& text) {
  return text.substr(0, text.find("output:\n")) +
         "output:\n  every_steps: 2\n  checkpoint_steps: 4\n";
}

/// configs/<stem>.yaml so, written into `dir`: the scene to restart.
fs::path checkpointed_config(const fs::path& dir, const std::string& stem) {
  const fs::path scene = dir / (stem + ".yaml");
  std::ofstream(scene) << with_frames_and_checkpoints(
      file_bytes(std::string(FISSURE_SOURCE_DIR "/configs/") + stem + ".yaml"));
  return scene;
}

void expect_restart_matches(const fs::path& dir, const fs::path& scene, int steps, int first_leg) {
  const std::string total = "--max-steps " + std::to_string(steps);
  EXPECT_EQ(run(scene, dir / "uninterrupted", {total}), 0);
  EXPECT_EQ(run(scene, dir / "restarted", {"--max-steps " + std::to_string(first_leg)}), 0);
  EXPECT_EQ(run(scene, dir / "restarted",
                {total, "--restart \"" + (dir / "restarted" / "checkpoint.h5").string() + "\""}),
            0);
  expect_same_run(dir / "uninterrupted", dir / "restarted");
}

/// `config` with the flow updated every 1 ms, a frame every 2 ms and a
/// checkpoint every 20 steps, run to `steps` uninterrupted and, into
/// "restarted", to `first_leg` steps and then restarted to `steps`; returns
/// the restarted run's summary after checking it matches.
nlohmann::json restart_an_hm_run(const fs::path& dir, const std::string& config,
                                 const std::string& transient, int steps, int first_leg) {
  const fs::path scene = dir / "hm.yaml";
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/" + config);
  if (!transient.empty()) text.replace(text.find("  hm:\n"), 6, transient + "\n  hm:\n");
  text.replace(text.find("{flow: 5 ms}"), 12, "{flow: 1 ms}");
  text = text.substr(0, text.find("output:\n")) +
         "output:\n  interval: 2 ms\n  checkpoint_steps: 20\n";
  std::ofstream(scene) << text;
  expect_restart_matches(dir, scene, steps, first_leg);
  return nlohmann::json::parse(file_bytes(dir / "restarted" / "summary.json"));
}

TEST(CheckpointRestart, TheTransientHmInjectionContinuesToTheSameBits) {
  // 80 steps (8 ms): the flow updates every 1 ms, before and after the
  // checkpoint at step 40.
  const nlohmann::json summary =
      restart_an_hm_run(scratch_dir("checkpoint_restart"), "flow_hm_injection.yaml",
                        "  transient: {scheme: backward_euler}", 80, 50);
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 40);
  EXPECT_GE(summary["processes"]["flow"]["flow_updates"].get<long>(), 6);
}

// After an initial stage (coupling.initial_equilibrium): the restart does
// not repeat it; the settled state, the flow's fixed-stress history and the
// stage's figures in summary.json come from the checkpoint. --max-steps
// bounds the stage and the run each.
TEST(CheckpointRestart, TheTransientHmInjectionAfterItsInitialStageContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const nlohmann::json summary =
      restart_an_hm_run(dir, "flow_hm_injection_transient.yaml", "", 150, 140);
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 140);
  // The stage's figures come from the checkpoint, as the uninterrupted run had them.
  const nlohmann::json uninterrupted =
      nlohmann::json::parse(file_bytes(dir / "uninterrupted" / "summary.json"));
  EXPECT_GT(summary["processes"]["coordinator"]["initial_equilibrium"]["steps"].get<long>(), 0);
  EXPECT_EQ(summary["processes"]["coordinator"]["initial_equilibrium"],
            uninterrupted["processes"]["coordinator"]["initial_equilibrium"]);
}

/// The heater scene with BDF2 and `thermal_keys` (lines of the thermal
/// section), a frame every 0.5 years and a checkpoint every 20 steps: 60
/// steps uninterrupted, and 50 (checkpoint at 40) then restarted. Returns
/// the restarted run's summary.
nlohmann::json expect_heater_restart(const std::string& name, const std::string& thermal_keys) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = dir / (name + ".yaml");
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/thermal_heater.yaml");
  text.replace(text.find("  time_step:"), 0, "  scheme: bdf2\n" + thermal_keys);
  text = text.substr(0, text.find("output:\n")) +
         "output:\n  interval: 0.5 yr\n  checkpoint_steps: 20\n";
  std::ofstream(scene) << text;
  const fs::path uninterrupted = dir / (name + "_uninterrupted"), restarted = dir / name;
  EXPECT_EQ(run(scene, uninterrupted, {"--max-steps 60"}), 0);
  EXPECT_EQ(run(scene, restarted, {"--max-steps 50"}), 0);
  EXPECT_EQ(run(scene, restarted,
                {"--max-steps 60", "--restart \"" + (restarted / "checkpoint.h5").string() + "\""}),
            0)
      << file_bytes(restarted.string() + ".log");
  expect_same_run(uninterrupted, restarted);
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(restarted / "summary.json"));
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 40);
  return summary;
}

// Heat conduction with BDF2 (its previous step is part of the state).
TEST(CheckpointRestart, TheThermalHeaterContinuesToTheSameBits) {
  const nlohmann::json summary = expect_heater_restart("heater", "");
  EXPECT_EQ(summary["processes"]["thermal"]["steps"], 60);
}

// The adaptive step (thermal.max_temperature_change): the step it proposes
// next and its counts are part of the state. The 0.2 K limit rejects the
// first tries (time_step, 0.1 yr, down to ~2 s at the canister's node), and
// the steps still grow after the checkpoint (1.9 s to 2.65 s over the 60
// steps): a restart that lost the proposed step would try 0.1 yr again.
TEST(CheckpointRestart, TheAdaptiveThermalHeaterContinuesToTheSameBits) {
  const nlohmann::json summary =
      expect_heater_restart("adaptive_heater", "  max_temperature_change: 0.2 K\n");
  const nlohmann::json& thermal = summary["processes"]["thermal"];
  EXPECT_EQ(thermal["steps"], 60);
  EXPECT_GT(thermal["adaptive_step"]["rejected_steps"], 0);
  EXPECT_LT(thermal["smallest_step"], thermal["largest_step"]);
  EXPECT_LE(thermal["largest_temperature_change"], 0.2);
}

// Fracture convection (thermal.convection): the water's temperatures at the
// fluid nodes and its energy terms are part of the state; the flow takes
// their viscosity at each update. configs/fracture_convection.yaml with
// 0.25 m elements, 24 hourly steps, a checkpoint every 10 (restarted from
// step 10 after a first leg of 15).
TEST(CheckpointRestart, TheFractureConvectionContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = dir / "convection.yaml";
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/fracture_convection.yaml");
  text.replace(text.find("element_size: 0.1 m"), 19, "element_size: 0.25 m");
  text =
      text.substr(0, text.find("output:\n")) + "output:\n  interval: 2 h\n  checkpoint_steps: 10\n";
  std::ofstream(scene) << text;
  EXPECT_EQ(run(scene, dir / "convection_uninterrupted", {"--max-steps 24"}), 0);
  EXPECT_EQ(run(scene, dir / "convection", {"--max-steps 15"}), 0);
  EXPECT_EQ(run(scene, dir / "convection",
                {"--max-steps 24",
                 "--restart \"" + (dir / "convection" / "checkpoint.h5").string() + "\""}),
            0)
      << file_bytes(dir.string() + "/convection.log");
  expect_same_run(dir / "convection_uninterrupted", dir / "convection");
  const nlohmann::json summary =
      nlohmann::json::parse(file_bytes(dir / "convection" / "summary.json"));
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 10);
  EXPECT_GT(summary["energy"]["heat"]["fracture_fluid"]["exchanged_with_rock"].get<double>(), 0);
}

/// configs/heated_drift.yaml with joints twice as far apart (about 300
/// blocks), mechanics and flow every `interval`, a frame every `interval`
/// and a checkpoint every 4 steps, to 1 year, and restarted from a first
/// leg to half a year; the two must match (expect_same_run). Returns the
/// restarted run's summary.
nlohmann::json restart_the_heated_drift(const std::string& interval) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = dir / "drift.yaml";
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/heated_drift.yaml");
  for (const std::string set : {"steep", "flat"}) {
    const std::string from = "name: " + set + ", dip: ";
    const std::size_t at = text.find("spacing: 1.2 m", text.find(from));
    text.replace(at, 14, "spacing: 2.4 m");
  }
  text.replace(text.find("{mechanics: 0.5 yr, flow: 0.5 yr}"), 33,
               "{mechanics: " + interval + ", flow: " + interval + "}");
  text = text.substr(0, text.find("output:\n")) + "output:\n  interval: " + interval +
         "\n  checkpoint_steps: 4\n";
  std::ofstream(scene) << text;
  const std::string year = "--end 31557600";
  EXPECT_EQ(run(scene, dir / "drift_uninterrupted", {year}), 0);
  EXPECT_EQ(run(scene, dir / "drift", {"--end 15778800"}), 0);
  EXPECT_EQ(run(scene, dir / "drift",
                {year, "--restart \"" + (dir / "drift" / "checkpoint.h5").string() + "\""}),
            0);
  expect_same_run(dir / "drift_uninterrupted", dir / "drift");
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(dir / "drift" / "summary.json"));
  EXPECT_EQ(summary["processes"]["coordinator"]["checkpoints"]["restarted"]["at_step"], 4);
  EXPECT_GT(summary["processes"]["coordinator"]["initial_equilibrium"]["steps"].get<long>(), 0);
  return summary;
}

// THM after an initial stage: the heated drift with mechanics and flow
// every quarter year. The thermal meshes are made on the blocks as cut, both
// in the stage's run and on the scene a restart starts from; the monitors'
// places in them were taken where the points had settled to (their
// temperatures differed in the 4th digit after a restart). The flow's
// linear solver counts from the checkpoint (it counted 4 against 6
// factorizations after the restart).
TEST(CheckpointRestart, TheHeatedDriftAfterItsInitialStageContinuesToTheSameBits) {
  restart_the_heated_drift("0.25 yr");
}

// The same drift with mechanics and flow every half year: the thermal
// factor of the steps before the checkpoint is kept across it, so the
// restart computes it again (with the checkpoint's a0 / dt) and does not
// count it: it counted 10 against 9 factorizations.
TEST(CheckpointRestart, TheHeatedDriftAfterItsInitialStageKeepsItsThermalFactorCount) {
  const nlohmann::json summary = restart_the_heated_drift("0.5 yr");
  EXPECT_GT(summary["processes"]["thermal"]["factorizations"].get<long>(), 0);
}

// The continuum (issue 24): the repository's far field with heat, fixed
// stress and BDF2, restarted at step 4 of 8 from its checkpoint, writes the
// same bits: the fields, the previous step BDF2 needs, and the staggered
// scheme's floors of its relative change come from the checkpoint.
TEST(CheckpointRestart, TheContinuumRepositoryContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart");
  const fs::path scene = dir / "repository.yaml";
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/continuum_repository.yaml");
  text.replace(text.find("  time_step: 10 yr"), 18, "  time_step: 10 yr\n  time_scheme: bdf2");
  text = with_frames_and_checkpoints(text);
  std::ofstream(scene) << text;
  expect_restart_matches(dir, scene, 8, 6);
}

// A permeability that follows the stress (issue 38): the Sellafield far
// field, restarted at step 4 of 8, writes the same bits: each step starts
// its tensors from its own start's fields (never from the last pass of the
// step before), so the restored fields give them again.
TEST(CheckpointRestart, TheStressDependentFarFieldContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_stress_permeability");
  fs::create_directories(dir / "sellafield_stress_study");
  fs::copy_file(FISSURE_SOURCE_DIR "/configs/sellafield_stress_study/stress.json",
                dir / "sellafield_stress_study" / "stress.json",
                fs::copy_options::overwrite_existing);
  expect_restart_matches(dir, checkpointed_config(dir, "sellafield_far_field"), 8, 6);
}

// A DDA block region tied to a continuum (issue 39, docs/architecture.md 5):
// a jointed square in a continuum whose top load grows over 8 steps,
// iterated with quasi-Newton, restarted at step 4: the tractions the blocks
// give the continuum are the DDA's to save (the shared field it writes),
// and the quasi-Newton history starts afresh in every coupling step.
TEST(CheckpointRestart, ATiedNearFieldContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_near_field");
  const fs::path scene = dir / "near_field.yaml";
  TiedSquare square;
  square.name = "near_field_restart";
  square.joint_sets =
      "    - {name: steep, dip: 70, spacing: 4 m, joint: glued}\n"
      "    - {name: flat, dip: 160, spacing: 4 m, joint: glued}";
  square.sxx = square.syy = -4;
  square.prestressed = true;
  square.top_extra = ", history: [[0, 1], [800000 s, 2]]";
  square.iteration = "{tolerance: 1e-5, max_iterations: 40, relaxation: quasi_newton}";
  square.end = "800000 s";
  std::ofstream(scene) << with_frames_and_checkpoints(tied_square_scene(square));
  expect_restart_matches(dir, scene, 8, 4);
}

// The same square's fracture network tied to the continuum for its water
// (flow/cubic_law/flow_ties.h), stored in the network (backward Euler) and
// in the continuum, 8 steps restarted at 4: the flows the mouths give the
// continuum are the flow's to save.
TEST(CheckpointRestart, ATiedFractureNetworkContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_near_field_water");
  const fs::path scene = dir / "near_field_water.yaml";
  TiedNetwork tied;
  tied.name = "near_field_water_restart";
  tied.transient = true;
  tied.time_step = "100000 s";
  tied.iteration = "{tolerance: 1e-8, max_iterations: 60, relaxation: quasi_newton}";
  tied.end = "800000 s";
  std::ofstream(scene) << with_frames_and_checkpoints(tied_network_scene(tied));
  expect_restart_matches(dir, scene, 8, 4);
}

// The heated drift in a jointed near field (configs/near_field_heated_drift.yaml):
// blocks, their heat and their water tied to the continuum, 8 Lie steps
// restarted at 4: what each tied process gives the continuum (tractions,
// heat fluxes, the mouths' flows) comes from the checkpoint.
TEST(CheckpointRestart, TheTiedHeatedDriftContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_near_field_drift");
  expect_restart_matches(dir, checkpointed_config(dir, "near_field_heated_drift"), 8, 4);
}

// Deformable DEM blocks around an opening tied to the continuum
// (testing::TiedOpening, zones of 1 m), 6 Lie steps restarted at 4: the
// tractions the DEM's blocks give the continuum are the DEM's to save.
TEST(CheckpointRestart, ATiedDemRegionContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_near_field_dem");
  const fs::path scene = dir / "near_field_dem.yaml";
  TiedOpening opening;
  opening.name = "near_field_dem_restart";
  opening.zone_size = 1;
  opening.steps = 6;
  std::ofstream(scene) << with_frames_and_checkpoints(tied_opening_scene(opening));
  expect_restart_matches(dir, scene, 6, 4);
}

// Dynamic DDA under a ground motion (issue 40, configs/masada_cliff.yaml
// shaken from the start): the driven base's position and velocity, its
// contacts' prescribed gaps and slips and the energy ledger's base work and
// boundary dissipation come from the checkpoint; the record and the viscous
// boundaries' edges from the scene again. Restarted at step 12 of 24.
TEST(CheckpointRestart, AShakenCliffContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_shaken");
  const fs::path scene = checkpointed_config(dir, "masada_cliff");
  std::string text = file_bytes(scene);
  const std::string record = "file: records/";
  text.replace(text.find(record), record.size(),
               std::string("file: ") + FISSURE_SOURCE_DIR + "/configs/records/");
  text.replace(text.find("start: 1 s"), 10, "start: 0 s");
  std::ofstream(scene) << text;
  expect_restart_matches(dir, scene, 24, 14);
  const nlohmann::json energy =
      nlohmann::json::parse(file_bytes(dir / "restarted" / "summary.json"))["energy"];
  EXPECT_NE(energy["base_work"].get<double>(), 0.0);
  EXPECT_NE(energy["boundary_dissipation"].get<double>(), 0.0);
}

// Augmented Lagrangian contacts (issue 40, configs/rock_burst_drift.yaml):
// the contacts' multipliers, the springs' stiffening and its calm steps,
// the spring constants of the reused factor and the ejected blocks' record
// come from the checkpoint. Restarted at step 12 of 24, while the drift's
// wall bursts.
TEST(CheckpointRestart, TheRockBurstContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_rock_burst");
  expect_restart_matches(dir, checkpointed_config(dir, "rock_burst_drift"), 24, 14);
  const nlohmann::json mechanics = nlohmann::json::parse(
      file_bytes(dir / "restarted" / "summary.json"))["processes"]["mechanics"];
  EXPECT_GT(mechanics["ejected_blocks"]["largest_speed"].get<double>(), 0.0);
}

// The explicit DEM (issue 37): the DEM brick wall restarted at step 4 of 12,
// while it still rings, writes the same bits: the contacts with their joint
// law states (by kind), lengths and keys, the DEM's own centroids, the
// half-step velocities, the moves since the last contact search and the
// cycle count come from the checkpoint.
TEST(CheckpointRestart, TheDemBrickWallContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_dem");
  expect_restart_matches(dir, checkpointed_config(dir, "dem_brick_wall"), 12, 6);
  const nlohmann::json summary =
      nlohmann::json::parse(file_bytes(dir / "restarted" / "summary.json"));
  EXPECT_EQ(summary["processes"]["dem"]["updates"], 12);
}

// The same with deformable bricks (configs/dem_zoned_wall.yaml): each
// zoned block's nodes, zones (deviatoric stresses, nodal pressures, areas),
// masses, topology and energy ledger come from the checkpoint, not from a
// mesh of the restored polygon.
TEST(CheckpointRestart, TheZonedDemWallContinuesToTheSameBits) {
  const fs::path dir = scratch_dir("checkpoint_restart_dem_zoned");
  expect_restart_matches(dir, checkpointed_config(dir, "dem_zoned_wall"), 8, 6);
}

}  // namespace
}  // namespace fissure::testing
