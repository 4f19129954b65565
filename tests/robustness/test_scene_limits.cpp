// Input that makes no sense is refused before anything runs (issue 22, item
// 3; docs/scene-reference.md, "Limits"): time controls that cannot work,
// magnitudes outside physics, blocks of too many vertices, and a bounded
// report of overlapping blocks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

/// kValid with `from` replaced by `to`: one error at `needle` (moved right by
/// `offset`) on `path` with every fragment.
void expect_refused(const std::string& from, const std::string& to, const std::string& needle,
                    size_t offset, const std::string& path,
                    const std::vector<std::string>& fragments) {
  SCOPED_TRACE(to);
  const std::string yaml = replace(kValid, from, to);
  const std::vector<std::string> lines = errors(yaml);
  EXPECT_EQ(lines.size(), 1u);
  expect_error(lines, at(yaml, needle, offset), path, fragments);
}

TEST(SceneLimits, TimeStepsThatDoublePrecisionCannotResolve) {
  // end = 1 s: a step below 1e-12 s is lost in t + dt.
  expect_refused("time_step: 1 ms", "time_step: 1e-13", "1e-13", 0, "mechanics.dda.time_step",
                 {"found '1e-13'", "at least 1e-12 x time.end = 1e-12 s"});
  expect_refused("end: 1", "end: 1\n  min_step: 1e-30", "1e-30", 0, "time.min_step",
                 {"found '1e-30'", "at least 1e-12 x time.end"});
  // Fine at the limits.
  EXPECT_NO_THROW(
      read_scene_text(replace(kValid, "time_step: 1 ms", "time_step: 1e-9"), "bad.yaml"));
}

TEST(SceneLimits, TimeStepBelowTheMinimumStep) {
  const std::string with_min = replace(kValid, "end: 1", "end: 1\n  min_step: 1 ms");
  const std::string yaml = replace(with_min, "time_step: 1 ms", "time_step: 0.1 ms");
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_EQ(lines.size(), 1u);
  expect_error(lines, at(yaml, "0.1 ms"), "mechanics.dda.time_step",
               {"found '0.1 ms'", "at least time.min_step = 0.001 s"});
}

TEST(SceneLimits, MoreStepsOrFramesThanARunCanTake) {
  expect_refused("end: 1", "end: 1e7", "1 ms", 0, "mechanics.dda.time_step",
                 {"the run would take more than 1e+09 steps", "or set time.max_steps"});
  // ... unless time.max_steps stops it earlier.
  EXPECT_NO_THROW(
      read_scene_text(replace(kValid, "end: 1", "end: 1e7\n  max_steps: 1000"), "bad.yaml"));
  expect_refused("end: 1", "end: 1\noutput:\n  interval: 1e-7", "1e-7", 0, "output.interval",
                 {"found '1e-7'", "at least time.end / 1e+06 = 1e-06 s", "or 0 (every_steps)"});
}

TEST(SceneLimits, TheDefaultMinimumStepFollowsAShortEndTime) {
  // A 1 microsecond run with 1 ns steps: the default min_step (1e-9 s for
  // long runs) would exceed the step; it is 1e-6 x end here.
  const std::string yaml =
      replace(replace(kValid, "end: 1", "end: 1e-6"), "time_step: 1 ms", "time_step: 1e-9");
  const Scene scene = read_scene_text(yaml, "bad.yaml");
  EXPECT_DOUBLE_EQ(scene.time.min_step, 1e-12);
}

TEST(SceneLimits, MagnitudesOutsidePhysics) {
  expect_refused("young_modulus: 50 GPa", "young_modulus: 5e15 Pa", "5e15", 0,
                 "materials[0].young_modulus",
                 {"found '5e15 Pa'", "expected a pressure of magnitude at most 1e+12 Pa",
                  "outside physics", "Limits"});
  expect_refused("density: 2650 kg/m^3", "density: 2650 t/m^3", "2650 t", 0, "materials[0].density",
                 {"of magnitude at most 100000 kg/m^3"});
  expect_refused("physics: [mechanics]", "physics: [mechanics]\ngravity: [0, -1e9]", "-1e9", 0,
                 "gravity[1]", {"expected an acceleration of magnitude at most 100000 m/s^2"});
  expect_refused("[[4, 1], [6, 1], [6, 2], [4, 2]]", "[[4, 1], [6, 1], [6, 2], [4, 2e9]]", "2e9", 0,
                 "blocks[1].vertices[3][1]", {"expected a length of magnitude at most 1e+07 m"});
  expect_refused("end: 1", "end: 1e20", "1e20", 0, "time.end",
                 {"expected a time of magnitude at most 1e+15 s"});
  // The fuzzer's 1e-320 GPa: finite, but the strain energy overflowed.
  expect_refused(
      "young_modulus: 50 GPa", "young_modulus: 1e-320 GPa", "1e-320", 0,
      "materials[0].young_modulus",
      {"found '1e-320 GPa'", "of magnitude at least 1e-50 (SI) or 0", "outside physics"});
}

TEST(SceneLimits, ABlockOfTooManyVertices) {
  std::string ring = "[";
  const int n = 10001;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979 * k / n;
    ring += (k ? ", [" : "[") + std::to_string(50 + 0.5 * std::cos(a)) + ", " +
            std::to_string(5 + 0.5 * std::sin(a)) + "]";
  }
  ring += "]";
  const std::string yaml = replace(kValid, "[[4, 1], [6, 1], [6, 2], [4, 2]]", ring);
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_GE(lines.size(), 1u);
  expect_error(lines, at(yaml, "vertices: " + ring), "blocks[1].vertices",
               {"found a polygon of 10001 vertices", "expected at most 10000 per block"});
}

TEST(SceneLimits, AnOverlapReportNamesABoundedNumberOfPairs) {
  // 300 copies of one block: 44,850 overlapping pairs, 20 named and a note.
  std::string copies;
  for (int k = 0; k < 300; ++k)
    copies +=
        "  - {name: copy" + std::to_string(k) + ", vertices: [[1, 1], [2, 1], [2, 2], [1, 2]]}\n";
  const std::string yaml = replace(kValid, "monitors:", copies + "monitors:");
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_EQ(lines.size(), 21u);
  int named = 0;
  for (const std::string& line : lines)
    named += line.find("overlapping block '") != std::string::npos;
  EXPECT_EQ(named, 20);
  EXPECT_NE(lines.back().find("found more than 20 pairs of overlapping blocks"), std::string::npos)
      << lines.back();
}

}  // namespace
}  // namespace fissure::testing
