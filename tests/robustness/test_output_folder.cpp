// A command without -o never overwrites the results of another input file
// (issue 34; coupling/output_folder.h, docs/output.md "Output folder"): the
// default folder is out/<file stem>, so two scenes with the same `name:` in
// different files write apart; a default folder whose summary.json records
// another scene file is refused (exit 1, the message naming both files and
// -o), with nothing written; a folder chosen with -o is written into, with a
// warning naming whose results it held; the same file reruns in place.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/io/summary_writer.h"
#include "coupling/output_folder.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/fissure_command.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A scratch folder with two scene files of the same stem and the same
/// `name:` in sub-folders a/ and b/ (they differ in their end time).
fs::path two_walls(const std::string& test) {
  const fs::path dir =
      fs::temp_directory_path() / ("fissure_output_folder_" + test + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  std::ofstream(dir / "a" / "wall.yaml") << "name: wall\n"
                                         << replace(kValid, "end: 1", "end: 2 ms");
  std::ofstream(dir / "b" / "wall.yaml") << "name: wall\n"
                                         << replace(kValid, "end: 1", "end: 3 ms");
  return dir;
}

std::string recorded_scene(const fs::path& folder) {
  const nlohmann::json j = nlohmann::json::parse(read(folder / "summary.json"));
  return j.value("scene_file", std::string());
}

TEST(output_folder, ADefaultFolderOfAnotherSceneFileIsRefused) {
  const fs::path dir = two_walls("refused");
  const std::string run = " -q --no-plots";
  std::string err;
  ASSERT_EQ(run_fissure("run a/wall.yaml" + run, dir, err), 0) << err;
  const fs::path out = dir / "out" / "wall";
  EXPECT_EQ(recorded_scene(out), fs::canonical(dir / "a" / "wall.yaml").string());
  const std::string before = read(out / "summary.json");
  const std::string monitors = read(out / "monitors.csv");

  // b/wall.yaml has the same stem and name: refused, nothing touched.
  EXPECT_EQ(run_fissure("run b/wall.yaml" + run, dir, err), 1);
  expect_contains(err, "error: out/wall holds the results of " +
                           fs::canonical(dir / "a" / "wall.yaml").string() +
                           " (out/wall/summary.json), not of b/wall.yaml; nothing was written. "
                           "Expected -o OUTDIR");
  EXPECT_EQ(read(out / "summary.json"), before);
  EXPECT_EQ(read(out / "monitors.csv"), monitors);
  EXPECT_EQ(run_fissure("mesh b/wall.yaml --no-plot", dir, err), 1);
  expect_contains(err, "out/wall holds the results of");
  EXPECT_EQ(read(out / "summary.json"), before);

  // The same file reruns into its folder, from another working path too.
  EXPECT_EQ(run_fissure("run ./a/../a/wall.yaml" + run, dir, err), 0) << err;
  EXPECT_TRUE(err.empty()) << err;

  // A folder chosen with -o is written into, with a warning.
  EXPECT_EQ(run_fissure("run b/wall.yaml -o out/wall" + run, dir, err), 0) << err;
  expect_contains(err, "warning: out/wall held the results of " +
                           fs::canonical(dir / "a" / "wall.yaml").string() +
                           "; they are replaced by those of b/wall.yaml");
  EXPECT_EQ(recorded_scene(out), fs::canonical(dir / "b" / "wall.yaml").string());
  fs::remove_all(dir);
}

TEST(output_folder, ScenesOfOneNameInFilesOfTwoStemsWriteApart) {
  const fs::path dir = two_walls("apart");
  fs::rename(dir / "b" / "wall.yaml", dir / "b" / "wall_b.yaml");
  std::string err;
  ASSERT_EQ(run_fissure("run a/wall.yaml -q --no-plots", dir, err), 0) << err;
  ASSERT_EQ(run_fissure("run b/wall_b.yaml -q --no-plots", dir, err), 0) << err;
  EXPECT_EQ(recorded_scene(dir / "out" / "wall"), fs::canonical(dir / "a" / "wall.yaml").string());
  EXPECT_EQ(recorded_scene(dir / "out" / "wall_b"),
            fs::canonical(dir / "b" / "wall_b.yaml").string());
  fs::remove_all(dir);
}

// A folder of a version that recorded no scene file is compared by the
// scene's name: another name is refused, the same one is rerun.
TEST(output_folder, AFolderWithoutASceneFileIsComparedByName) {
  const fs::path dir = two_walls("by_name");
  fs::create_directories(dir / "out" / "wall");
  std::ofstream(dir / "out" / "wall" / "summary.json")
      << R"({"scene": "brick", "status": "completed"})";
  std::string err;
  EXPECT_EQ(run_fissure("run a/wall.yaml -q --no-plots", dir, err), 1);
  expect_contains(err, "holds the results of 'brick' (by its name; the file is not recorded)");
  std::ofstream(dir / "out" / "wall" / "summary.json")
      << R"({"scene": "wall", "status": "completed"})";
  EXPECT_EQ(run_fissure("run a/wall.yaml -q --no-plots", dir, err), 0) << err;
  fs::remove_all(dir);
}

// `fissure rev` writes to out/rev/<study file stem> and checks rev.json's
// study_file the same way.
TEST(output_folder, AStudyFolderIsCheckedByItsRevJson) {
  const fs::path dir = two_walls("rev");
  EXPECT_EQ(default_output_folder("configs/flow_rev_study.yaml", "rev"),
            fs::path("out/rev/flow_rev_study"));
  const fs::path out = dir / "out" / "rev" / "study";
  fs::create_directories(out);
  std::ofstream(out / "rev.json") << nlohmann::json{
      {"name", "study"},
      {"study_file",
       recorded_file_path(dir / "a" /
                          "s.yaml")}}.dump();
  EXPECT_EQ(check_output_folder(out, kRevRecord, dir / "a" / "s.yaml", "study", false),
            std::nullopt);
  EXPECT_THROW(check_output_folder(out, kRevRecord, dir / "b" / "s.yaml", "study", false),
               OutputFolderError);
  const auto warning = check_output_folder(out, kRevRecord, dir / "b" / "s.yaml", "study", true);
  ASSERT_TRUE(warning.has_value());
  expect_contains(*warning, "held the results of " + recorded_file_path(dir / "a" / "s.yaml"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fissure::testing
