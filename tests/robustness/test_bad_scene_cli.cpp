// Bad scenes beyond single edits: random corruptions of a valid scene are
// reported in the error format and never crash the parser, and the command
// line (`fissure validate`, `fissure run`) exits non-zero with the errors on
// stderr and runs nothing; its times take units as the scene's do (`--end
// 1yr`, `--end "30 d"`), and a unit it does not know names the option.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "core/base/errors.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/fissure_command.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

TEST(bad_scenes, RandomCorruptionsAreReportedNotCrashed) {
  // Single-character edits of a valid scene (deterministic): each either
  // parses or throws one SceneError whose lines all have the message format.
  const std::string alphabet = "0123456789-.,:[]{} \n#'\"abxyz";
  std::mt19937 random(12345);
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string yaml = kValid;
    for (int edit = 0; edit < 1 + trial % 3; ++edit) {
      const size_t pos = random() % yaml.size();
      const char c = alphabet[random() % alphabet.size()];
      switch (random() % 3) {
        case 0:
          yaml[pos] = c;
          break;
        case 1:
          yaml.insert(yaml.begin() + pos, c);
          break;
        default:
          yaml.erase(pos, 1);
          break;
      }
    }
    try {
      read_scene_text(yaml, "bad.yaml");
    } catch (const SceneError& e) {
      ++rejected;
      std::istringstream lines(e.what());
      for (std::string line; std::getline(lines, line);) {
        ASSERT_EQ(line.rfind("bad.yaml:", 0), 0u) << line << "\nin\n" << yaml;
        ASSERT_NE(line.find("; expected "), std::string::npos) << line << "\nin\n" << yaml;
      }
    } catch (const std::exception& e) {
      FAIL() << "unexpected exception '" << e.what() << "' for\n" << yaml;
    }
  }
  EXPECT_GT(rejected, 1000);
}

using testing::run_fissure;

TEST(bad_scenes, CommandLineValidate) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fissure_bad_scenes_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path bad = dir / "bad.yaml";
  const std::filesystem::path good = dir / "good.yaml";
  std::ofstream(bad) << kSeveralErrors;
  std::ofstream(good) << kValid;

  std::string err;
  const int bad_code = run_fissure("validate \"" + bad.string() + "\"", dir, err);
  EXPECT_NE(bad_code, 0);
  EXPECT_NE(err.find("invalid scene"), std::string::npos) << err;
  EXPECT_NE(err.find(bad.string() + ":4:14: materials[0].density: found '-1'; expected a "
                                    "density > 0"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find(bad.string() + ":10:5: joints[0].cohesoin: unknown key"), std::string::npos)
      << err;

  // Nothing runs on an invalid scene: no output folder appears.
  const std::filesystem::path out = dir / "out";
  EXPECT_NE(run_fissure("run \"" + bad.string() + "\" -q -o \"" + out.string() + "\"", dir, err),
            0);
  EXPECT_FALSE(std::filesystem::exists(out));

  EXPECT_EQ(run_fissure("validate \"" + good.string() + "\"", dir, err), 0) << err;
  EXPECT_TRUE(err.empty()) << err;
  std::filesystem::remove_all(dir);
}

// What only a process finds when it starts (a flow boundary that no
// fracture reaches: the network exists once the flow builds it) is found by
// `fissure validate` too, located, and the run writes nothing (the fuzzer's
// class VALIDATE-ACCEPTS-RUN-REJECTS: 33 of 10,000 mutated scenes).
TEST(bad_scenes, CommandLineValidateFindsWhatTheProcessesFindWhenTheyStart) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("fissure_validate_processes_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(FISSURE_SOURCE_DIR "/configs/flow_dfn_steady.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  // The domain's top-right corner moved in by 0.5 m: its right side is no
  // longer the vertical side named 'right', and no node of the network lies
  // on 'right' (fuzz case 2436).
  const std::string corner = "[60, 30]";
  ASSERT_NE(yaml.find(corner), std::string::npos);
  yaml.replace(yaml.find(corner), corner.size(), "[59.5, 30]");
  const std::filesystem::path scene = dir / "unreachable.yaml";
  std::ofstream(scene) << yaml;

  std::string err;
  EXPECT_EQ(run_fissure("validate \"" + scene.string() + "\"", dir, err), 1);
  EXPECT_NE(err.find(scene.string() + ":"), std::string::npos) << err;
  EXPECT_NE(err.find("flow.conditions[1].boundary: found 'right', which holds no node of the "
                     "fracture network"),
            std::string::npos)
      << err;
  EXPECT_EQ(
      run_fissure("validate \"" FISSURE_SOURCE_DIR "/configs/flow_dfn_steady.yaml\"", dir, err), 0)
      << err;
  std::filesystem::remove_all(dir);
}

// `fissure run --end` reads its time as a scene does (core/scene/units.h):
// seconds, or a number and its unit with or without a space; an unknown unit
// or a time that is not positive is an error naming the option, before
// anything runs.
// What is not a scene file is refused before it is read whole (issue 35):
// a device such as /dev/zero at once (it has no end), and a pipe once it has
// given more than the 256 MB Fissure reads.
TEST(bad_scenes, DevicesAndEndlessInputAreRefusedAtOnce) {
  const std::filesystem::path dir = testing::scratch_dir("bad_scene_cli");
  std::string err;
  EXPECT_EQ(run_fissure("validate /dev/zero", dir, err), 1);
  testing::expect_contains(err, "/dev/zero:1:1: (document): found a device, not a file");
  // A named pipe that a writer fills with 300 MB of zeros.
  const std::string fill = "cd \"" + dir.string() +
                           "\" && mkfifo pipe.yaml && ((head -c 300000000 /dev/zero > pipe.yaml) "
                           "2> /dev/null &)";
  ASSERT_EQ(std::system(fill.c_str()), 0);
  EXPECT_EQ(run_fissure("validate pipe.yaml", dir, err), 1);
  testing::expect_contains(err,
                           "found more than 256 MB; Fissure reads input files of at most 256 MB");
}

TEST(bad_scenes, CommandLineTimesTakeUnits) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fissure_cli_units_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "wall.yaml") << kValid;
  const auto simulated_time = [&](const std::string& folder) {
    std::ifstream in(dir / folder / "summary.json");
    std::ostringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    const size_t at = text.find("\"simulated_time\": ");
    return at == std::string::npos ? -1.0 : std::stod(text.substr(at + 18));
  };
  std::string err;
  for (const auto& [end, folder] : {std::pair<std::string, std::string>{"2ms", "glued"},
                                    {"\"2 ms\"", "spaced"},
                                    {"0.002", "seconds"},
                                    {"2e-3s", "exponent"}}) {
    EXPECT_EQ(run_fissure("run wall.yaml -q --no-plots --end " + end + " -o " + folder, dir, err),
              0)
        << end << ": " << err;
    EXPECT_NEAR(simulated_time(folder), 0.002, 1e-12) << end;
  }
  EXPECT_EQ(run_fissure("run wall.yaml -q --no-plots --end 3fortnights -o bad", dir, err), 1);
  expect_contains(err, "--end");
  expect_contains(err, "found '3fortnights' with unknown unit 'fortnights'; expected a time");
  EXPECT_EQ(run_fissure("run wall.yaml -q --no-plots --end \"2 m\" -o bad", dir, err), 1);
  expect_contains(err, "found '2 m', a length; expected a time");
  EXPECT_EQ(run_fissure("run wall.yaml -q --no-plots --end 0d -o bad", dir, err), 1);
  expect_contains(err, "found '0d'; expected a time > 0");
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fissure::testing
