// summary.json (core/io/summary_writer): keys and values, valid JSON even with
// NaN, infinity and bytes that are not UTF-8, and atomic replacement.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/io/summary_writer.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fs = std::filesystem;
using namespace fissure;
using fissure::test::read_text;
using nlohmann::json;

namespace {

/// summary.json in this test's own scratch folder.
fs::path fresh_file() {
  return fs::path(fissure::testing::scratch_dir("summary_writer")) / "summary.json";
}

RunSummary example() {
  RunSummary s;
  s.scene = "brick_wall";
  s.status = "completed";
  s.steps = 1234;
  s.simulated_time = 0.5;
  s.time_unit = {"d", 86400};
  s.wall_seconds = 2.25;
  s.output_frames = 11;
  s.processes["dda"] = {{"open_close_iterations", 4567}, {"time_step_cuts", 3}};
  s.monitors["top"] = {{"ux", 1e-3}, {"uy", -2.5e-4}};
  s.energy["kinetic"] = 12.5;
  return s;
}

}  // namespace

TEST(summary_writer, WritesEveryKeyInOrderPrettyPrinted) {
  const fs::path file = fresh_file();
  write_summary(file, example());
  const std::string text = read_text(file);
  const json j = json::parse(text);

  EXPECT_EQ(j["scene"], "brick_wall");
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["message"], "");
  EXPECT_EQ(j["steps"], 1234);
  EXPECT_EQ(j["simulated_time"], 0.5);
  EXPECT_EQ(j["time_unit"]["name"], "d");
  EXPECT_EQ(j["time_unit"]["seconds"], 86400);
  EXPECT_EQ(j["wall_seconds"], 2.25);
  EXPECT_EQ(j["output_frames"], 11);
  EXPECT_EQ(j["processes"]["dda"]["open_close_iterations"], 4567);
  EXPECT_EQ(j["monitors"]["top"]["uy"], -2.5e-4);
  EXPECT_EQ(j["energy"]["kinetic"], 12.5);

  // Keys in the documented order, one per line, indented by two spaces.
  std::size_t previous = 0;
  for (const char* key : {"scene", "status", "message", "steps", "simulated_time", "time_unit",
                          "wall_seconds", "output_frames", "processes", "monitors", "energy"}) {
    const std::size_t at = text.find(std::string("\n  \"") + key + "\": ");
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, previous) << key;
    previous = at;
  }
  EXPECT_EQ(text.back(), '\n');
}

TEST(summary_writer, NanAndInfinityBecomeNull) {
  const fs::path file = fresh_file();
  RunSummary s = example();
  s.status = "diverged";
  s.simulated_time = std::numeric_limits<double>::quiet_NaN();
  s.wall_seconds = std::numeric_limits<double>::infinity();
  s.energy["kinetic"] = -std::numeric_limits<double>::infinity();
  s.monitors["top"]["ux"] = std::nan("");
  write_summary(file, s);

  const json j = json::parse(read_text(file));  // throws if invalid
  EXPECT_TRUE(j["simulated_time"].is_null());
  EXPECT_TRUE(j["wall_seconds"].is_null());
  EXPECT_TRUE(j["energy"]["kinetic"].is_null());
  EXPECT_TRUE(j["monitors"]["top"]["ux"].is_null());
  EXPECT_EQ(j["monitors"]["top"]["uy"], -2.5e-4);
  EXPECT_EQ(j["status"], "diverged");
}

TEST(summary_writer, MessageThatIsNotUtf8StillGivesValidJson) {
  const fs::path file = fresh_file();
  RunSummary s = example();
  s.status = "failed";
  s.message = "cannot open /data/r\xe9sultat.yaml";  // Latin-1 e-acute
  ASSERT_NO_THROW(write_summary(file, s));
  const json j = json::parse(read_text(file));
  EXPECT_EQ(j["message"].get<std::string>().substr(0, 15), "cannot open /da");
}

TEST(summary_writer, ReplacesAnOlderSummaryAtomically) {
  const fs::path file = fresh_file();
  RunSummary s = example();
  s.status = "running";
  write_summary(file, s);
  s.status = "completed";
  write_summary(file, s);
  EXPECT_EQ(json::parse(read_text(file))["status"], "completed");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator()), 1);
}

TEST(summary_writer, UnwritableFolderIsAnIoErrorNamingTheFile) {
  const fs::path file = fs::path(FISSURE_BINARY_DIR) / "test-output" / "no" / "such" / "s.json";
  try {
    write_summary(file, example());
    FAIL() << "no error for a missing folder";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json"), std::string::npos) << e.what();
  }
}
