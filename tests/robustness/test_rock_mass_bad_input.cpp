// Bad `rock_mass` input (issue 3, "Bad input"; docs/rock-mass.md section 5):
// joint sets with zero or negative spacing, fractures outside the domain,
// domains and excavations that are not simple polygons, and densities that
// would give more fractures or blocks than the configurable maxima, laws whose
// size cannot be estimated or whose apertures spread too widely. Each is
// one clear error "FILE:LINE:COLUMN: KEY.PATH: found ...; expected ...",
// before any computation; an oversized rock mass is refused from its
// estimate, in milliseconds and without allocating it.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "coupling/process_registry.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

using testing::at;
using testing::expect_error;

const std::string kRockMass = R"(physics: [mechanics]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
rock_mass:
  domain: [[0, 0], [20, 0], [20, 10], [0, 10]]
  excavations:
    - {name: adit, vertices: [[8, 4], [12, 4], [12, 6], [8, 6]]}
  joint_sets:
    - {name: bedding, dip: 10, spacing: 2 m}
  dfn:
    - name: random
      density: {p21: 0.5 1/m}
      orientation: {distribution: uniform}
      length: 3 m
  fractures:
    - {from: [1, 1], to: [5, 4]}
mechanics: {}
time:
  end: 0.01
)";

/// The error lines for `yaml`, parsed with the rock-mass generator.
std::vector<std::string> errors(const std::string& yaml) {
  return testing::errors(yaml);
}

/// The valid scene with `from` replaced by `to`; expects the error at the
/// first `needle` (+ offset) with `path` and `fragments`.
void expect_broken(const std::string& from, const std::string& to, const std::string& needle,
                   size_t offset, const std::string& path,
                   const std::vector<std::string>& fragments) {
  SCOPED_TRACE(to);
  const std::string yaml = testing::replace(kRockMass, from, to);
  expect_error(errors(yaml), at(yaml, needle, offset), path, fragments);
}

TEST(rock_mass_bad_input, TheValidSceneIsValid) {
  const Scene s = read_scene_text(kRockMass, "bad.yaml");
  EXPECT_GT(s.blocks.size(), 3u);
}

// --- joint sets -------------------------------------------------------------

TEST(rock_mass_bad_input, ZeroOrNegativeSpacing) {
  const std::string set = "spacing: 2 m}";
  expect_broken(set, "spacing: 0}", "spacing: 0", 9, "rock_mass.joint_sets[0].spacing",
                {"found '0'", "expected a length > 0"});
  expect_broken(set, "spacing: -2 m}", "spacing: -2", 9, "rock_mass.joint_sets[0].spacing",
                {"found '-2 m'", "expected a length > 0"});
  expect_broken(set, "spacing: 2 m, spacing_spread: 2 m}", "spacing_spread: 2", 16,
                "rock_mass.joint_sets[0].spacing_spread",
                {"found 2 m with spacing 2 m", "expected a spread smaller than the spacing"});
  const std::string no_spacing = testing::replace(kRockMass, ", spacing: 2 m}", "}");
  expect_error(errors(no_spacing), at(no_spacing, "{name: bedding"),
               "rock_mass.joint_sets[0].spacing", {"key is missing", "expected a length"});
}

TEST(rock_mass_bad_input, OtherJointSetAndDfnRanges) {
  const std::string set = "spacing: 2 m}";
  expect_broken(set, "spacing: 2 m, trace_length: -1 m}", "trace_length: -1", 14,
                "rock_mass.joint_sets[0].trace_length", {"found '-1 m'", "expected a length > 0"});
  expect_broken(set, "spacing: 2 m, bridge_length: 1 m}", "bridge_length", 15,
                "rock_mass.joint_sets[0].bridge_length",
                {"found a bridge length without trace_length", "expected trace_length too"});
  expect_broken(set, "spacing: 2 m, phase: 1}", "phase: 1", 7, "rock_mass.joint_sets[0].phase",
                {"found '1'", "expected a number in [0, 1)"});
  expect_broken("p21: 0.5 1/m", "p21: 0", "p21: 0", 5, "rock_mass.dfn[0].density.p21",
                {"found '0'", "expected a length per area > 0"});
  expect_broken("length: 3 m", "length: {distribution: uniform, min: 4 m, max: 2 m}",
                "{distribution: uniform, min", 0, "rock_mass.dfn[0].length",
                {"found min = 4 m and max = 2 m", "expected min < max"});
}

TEST(rock_mass_bad_input, AperturesBeyondTenCentimetres) {
  // An aperture typed without its unit ('40' for 40 um) is 40 m: the flow's
  // conductances then spanned 30 orders of magnitude and CHOLMOD found the
  // network matrix indefinite (fuzz case 7609).
  const std::string set = "spacing: 2 m}";
  expect_broken(set, "spacing: 2 m, aperture: 40}", "aperture: 40", 10,
                "rock_mass.joint_sets[0].aperture",
                {"found '40'", "expected a length in (0, 0.1] m"});
  expect_broken("length: 3 m",
                "length: 3 m\n      aperture: {distribution: log_normal, mean: 40, "
                "std: 10 um}",
                "mean: 40", 6, "rock_mass.dfn[0].aperture.mean",
                {"found '40'", "expected a length in (0, 0.1] m"});
  expect_broken("to: [5, 4]}", "to: [5, 4], aperture: 0.2 m}", "aperture: 0.2", 10,
                "rock_mass.fractures[0].aperture",
                {"found '0.2 m'", "expected a length in (0, 0.1] m"});
  // 10 cm itself is allowed.
  EXPECT_NO_THROW(read_scene_text(
      testing::replace(kRockMass, set, "spacing: 2 m, aperture: 10 cm}"), "ok.yaml"));
}

// --- geometry ---------------------------------------------------------------

TEST(rock_mass_bad_input, FractureOutsideTheDomain) {
  const std::string fracture = "{from: [1, 1], to: [5, 4]}";
  expect_broken(fracture, "{from: [30, 1], to: [40, 4]}", "{from: [30", 0, "rock_mass.fractures[0]",
                {"found a fracture from (30, 1) to (40, 4), outside the domain",
                 "expected a fracture that reaches into the domain"});
  // Along a side, on the boundary only: no rock on either side of it.
  expect_broken(fracture, "{from: [-5, 10], to: [25, 10]}", "{from: [-5", 0,
                "rock_mass.fractures[0]", {"outside the domain"});
  expect_broken(fracture, "{from: [1, 1], to: [1, 1]}", "{from: [1, 1], to: [1, 1]}", 0,
                "rock_mass.fractures[0]", {"found a fracture of zero length"});
  // Both ends outside but crossing the rock: accepted, and clipped.
  EXPECT_NO_THROW(read_scene_text(
      testing::replace(kRockMass, fracture, "{from: [-5, 1], to: [25, 9]}"), "bad.yaml"));
}

TEST(rock_mass_bad_input, DomainThatIsNotASimplePolygon) {
  const std::string domain = "domain: [[0, 0], [20, 0], [20, 10], [0, 10]]";
  const std::string expected = "expected a domain: a simple polygon";
  expect_broken(domain, "domain: [[0, 0], [20, 10], [20, 0], [0, 10]]", "[[0, 0], [20, 10]", 0,
                "rock_mass.domain", {"intersect", expected});
  expect_broken(domain, "domain: [[0, 0], [10, 0], [20, 0]]", "[[0, 0], [10, 0]", 0,
                "rock_mass.domain", {"zero area", expected});
  expect_broken(domain, "domain: [[0, 0], [20, 0]]", "[[0, 0], [20, 0]]", 0, "rock_mass.domain",
                {"2 vertices", expected});
  expect_broken(domain, "domain: [[0, 0], [20, 0], [20, 0], [20, 10], [0, 10]]",
                "[[0, 0], [20, 0], [20, 0]", 0, "rock_mass.domain", {"coincide", expected});
  // A domain that touches itself at one vertex (two squares corner to corner).
  expect_broken(domain,
                "domain: [[0, 0], [10, 0], [10, 5], [20, 5], [20, 10], [10, 10], [10, 5], "
                "[0, 5]]",
                "[[0, 0], [10, 0], [10, 5]", 0, "rock_mass.domain", {"touch at (10, 5)", expected});
}

TEST(rock_mass_bad_input, ExcavationsThatAreNotSimpleOrMissTheDomain) {
  const std::string adit = "vertices: [[8, 4], [12, 4], [12, 6], [8, 6]]";
  expect_broken(adit, "vertices: [[8, 4], [12, 6], [12, 4], [8, 6]]", "[[8, 4], [12, 6]", 0,
                "rock_mass.excavations[0].vertices",
                {"intersect", "expected an excavation: a simple polygon"});
  expect_broken(adit, "vertices: [[30, 4], [32, 4], [32, 6], [30, 6]]", "[[30, 4]", 0,
                "rock_mass.excavations[0].vertices",
                {"found an excavation outside the domain", "expected one that overlaps it"});
  expect_broken("{name: adit, vertices", "{name: top, vertices", "top", 0,
                "rock_mass.excavations[0].name", {"found 'top', the name of a domain side"});
}

// --- size limits ------------------------------------------------------------

/// A jagged star of n vertices around (10, 5) inside the valid domain's box:
/// simple, but 10,001 vertices are one too many for a block outline.
std::string jagged_loop(int n, double radius) {
  std::ostringstream out;
  out << "[";
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.141592653589793 * k / n, r = radius * (k % 2 ? 0.6 : 1.0);
    out << (k ? ", " : "") << "[" << 10 + r * std::cos(a) << ", " << 5 + r * std::sin(a) << "]";
  }
  out << "]";
  return out.str();
}

TEST(rock_mass_bad_input, DomainAndExcavationsOfMoreVerticesThanABlockMayHave) {
  expect_broken("domain: [[0, 0], [20, 0], [20, 10], [0, 10]]", "domain: " + jagged_loop(10001, 9),
                "domain: [[", 8, "rock_mass.domain",
                {"found a polygon of 10001 vertices; expected a domain of at most 10000 "
                 "vertices"});
  expect_broken("vertices: [[8, 4], [12, 4], [12, 6], [8, 6]]",
                "vertices: " + jagged_loop(10001, 1.5), "vertices: [[1", 10,
                "rock_mass.excavations[0].vertices",
                {"found a polygon of 10001 vertices; expected an excavation of at most 10000"});
  // A circle of 1e9 segments is refused before its points are made (it ran
  // out of memory: fuzz seed 2024, case 6270).
  expect_broken("{name: adit, vertices: [[8, 4], [12, 4], [12, 6], [8, 6]]}",
                "{name: adit, circle: {centre: [10, 5], radius: 1, segments: 1000000000}}",
                "1000000000", 0, "rock_mass.excavations[0].circle.segments",
                {"found '1000000000'", "10000"});
}

TEST(rock_mass_bad_input, DensitiesBeyondMaxBlocksAreRefusedFromTheEstimate) {
  // Two orthogonal sets 1 mm apart in 20 m x 10 m: 2e8 blocks (P21 = 1000 /m
  // each, crossing 1e6 times per m^2), each at least 4 vertices x 16 bytes:
  // over 12 GB. The estimate refuses it at the `rock_mass` key, before a
  // single trace is drawn (the memory check is the command-line test below).
  const std::string yaml = testing::replace(kRockMass, "{name: bedding, dip: 10, spacing: 2 m}",
                                            "{name: bedding, dip: 0, spacing: 1 mm}\n"
                                            "    - {name: cross, dip: 90, spacing: 1 mm}");
  const std::vector<std::string> lines = errors(yaml);
  expect_error(lines, at(yaml, "rock_mass:"), "rock_mass",
               {"would cut the rock into about 2e+08 blocks", "more than max_blocks = 50000",
                "expected lower densities, larger spacings or a larger max_blocks"});

  // The limit is configurable: the valid scene (about 50 blocks expected)
  // under max_blocks = 10.
  const std::string small =
      testing::replace(kRockMass, "mechanics: {}", "  max_blocks: 10\nmechanics: {}");
  expect_error(errors(small), at(small, "rock_mass:"), "rock_mass",
               {"would cut the rock into about", "more than max_blocks = 10"});
}

TEST(rock_mass_bad_input, DensitiesBeyondMaxFracturesAreRefusedFromTheEstimate) {
  // P21 = 1e5 /m of 3 m fractures: P20 = 3.33e4 /m^2 over the (20 + 3) x
  // (10 + 3) m^2 window (dfn_generator.h), 9.97e6 fractures.
  const std::string yaml = testing::replace(kRockMass, "p21: 0.5 1/m", "p21: 1e5 1/m");
  expect_error(errors(yaml), at(yaml, "rock_mass:"), "rock_mass",
               {"would generate about 9.97e+06 fractures", "more than max_fractures = 100000"});
}

TEST(rock_mass_bad_input, LawsWhoseSizeOrSpreadCannotBeBounded) {
  // A power law of exponent 10 down to 1e-40 m: its moments overflow
  // (min^-9), so the estimated number of fractures is not a number. Refused,
  // not drawn as none.
  expect_broken(
      "length: 3 m",
      "length: {distribution: truncated_power_law, exponent: 10, min: 1e-40 m, "
      "max: 1 m}",
      "rock_mass:", 0, "rock_mass",
      {"found joint sets or DFN families whose size cannot be estimated", "moments overflow"});
  // Log-normal apertures 1000 times wider than their mean: conductances over
  // 60 orders of magnitude (a REV study failed in CHOLMOD, issue 35).
  expect_broken("length: 3 m",
                "length: 3 m\n      aperture: {distribution: log_normal, mean: 70 um, std: 70 mm}",
                "{distribution: log_normal", 0, "rock_mass.dfn[0].aperture",
                {"found std = 0.07 m with mean = 7e-05 m",
                 "expected a standard deviation at most 10 x the mean"});
}

TEST(rock_mass_bad_input, MoreBlocksThanMaxBlocksAfterCutting) {
  // The estimate treats explicit fractures as a random line process: three
  // horizontal and three vertical fractures from side to side of a 4 m x 4 m
  // box (P21 = 1.5 /m, half at 0 and half at 90 deg: E|sin| = 1/2) are
  // expected to cross 0.5 x 16 x 1.5^2 x 1/2 = 9 times (10 blocks), but cut
  // 16 blocks. The limit is checked again on the cut.
  std::string yaml = testing::replace(kRockMass, "[[0, 0], [20, 0], [20, 10], [0, 10]]",
                                      "[[0, 0], [4, 0], [4, 4], [0, 4]]");
  yaml = testing::replace(yaml,
                          "  excavations:\n    - {name: adit, vertices: [[8, 4], [12, 4], [12, 6], "
                          "[8, 6]]}\n",
                          "");
  const size_t sets = yaml.find("  joint_sets:"), end = yaml.find("mechanics: {}");
  yaml.replace(sets, end - sets,
               "  fractures:\n"
               "    - {from: [0, 1], to: [4, 1]}\n    - {from: [0, 2], to: [4, 2]}\n"
               "    - {from: [0, 3], to: [4, 3]}\n    - {from: [1, 0], to: [1, 4]}\n"
               "    - {from: [2, 0], to: [2, 4]}\n    - {from: [3, 0], to: [3, 4]}\n"
               "  max_blocks: 12\n");
  expect_error(errors(yaml), at(yaml, "rock_mass:"), "rock_mass",
               {"found 16 blocks after cutting, more than max_blocks = 12"});
}

TEST(rock_mass_bad_input, CommandLineMeshRefusesAnOversizedRockMassWithoutMemory) {
  // `fissure mesh` on the 2e8-block scene: exit code 1, the message on
  // stderr, and the child's peak memory far below what the blocks would
  // need (12 GB): the program's own footprint (libraries, < 200 MB here).
  const std::filesystem::path dir = testing::scratch_dir("rock_mass_bad_input");
  const std::filesystem::path scene = dir / "dense.yaml";
  std::ofstream(scene) << testing::replace(kRockMass, "{name: bedding, dip: 10, spacing: 2 m}",
                                           "{name: bedding, dip: 0, spacing: 1 mm}\n"
                                           "    - {name: cross, dip: 90, spacing: 1 mm}");
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string command = std::string("\"") + FISSURE_APP + "\" mesh \"" + scene.string() +
                              "\" -o \"" + (dir / "out").string() + "\" > /dev/null 2> \"" +
                              err.string() + "\"";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::ostringstream text;
  text << std::ifstream(err).rdbuf();
  EXPECT_NE(text.str().find(scene.string() + ":6:1: rock_mass: found joint sets and DFN families "
                                             "that would cut the rock into about 2e+08 blocks"),
            std::string::npos)
      << text.str();
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing is written for an invalid scene";
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 200 * 1024) << "peak RSS of the child, KiB";
}

}  // namespace
}  // namespace fissure
