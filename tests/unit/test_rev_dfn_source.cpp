// The REV study's `network.type: dfn` (flow/rev/rev_dfn_source.h): families with
// the keys of a scene's `rock_mass.dfn[]`, drawn by the rock-mass DFN
// generator (rockmass/dfn_generator.h) over the study's region.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/base/errors.h"
#include "flow/rev/rev_dfn_source.h"
#include "rockmass/dfn_generator.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

constexpr double kRegion = 20;  // m
constexpr double kLength = 1;   // m, every fracture
constexpr double kP20 = 1;      // 1/m^2

std::string study_yaml(int seed, const std::string& family_extra = "") {
  return "name: dfn_study\n"
         "network:\n"
         "  type: dfn\n"
         "  centre: [5, -3]\n"
         "  dfn:\n"
         "    region: 20 m\n"
         "    seed: " +
         std::to_string(seed) +
         "\n"
         "    families:\n"
         "      - name: random\n"
         "        density: {p20: 1 1/m^2}\n"
         "        orientation: {distribution: uniform}\n"
         "        length: 1 m\n"
         "        aperture: 100 um\n" +
         family_extra + "sizes: [4, 8]\nrealizations: 3\n";
}

flow::RevStudy read_study(const std::string& yaml) {
  const std::filesystem::path file =
      std::filesystem::path(testing::scratch_dir("rev_dfn_source")) / "study.yaml";
  std::ofstream(file) << yaml;
  return flow::read_rev_study(file, rev_dfn_source_factory());
}

std::string study_error(const std::string& yaml) {
  try {
    read_study(yaml);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

/// A square that holds every drawn fracture whole (centres lie within
/// kLength / 2 of the region), so the graph has all of them unclipped.
FractureGraph whole_network(const flow::DomainSource& source, int realization) {
  return source.domain(realization, kRegion + 4 * kLength, 0);
}

/// Centres of the fractures of the graph (in the square's frame): the
/// midpoints of the two nodes of each fracture farthest apart.
std::vector<Vec2> fracture_centres(const FractureGraph& g) {
  std::map<int, std::vector<Vec2>> points;
  for (const FractureSegment& s : g.segments) {
    points[s.fracture].push_back(g.nodes[s.node_a]);
    points[s.fracture].push_back(g.nodes[s.node_b]);
  }
  std::vector<Vec2> centres;
  for (const auto& [fracture, p] : points) {
    std::pair<Vec2, Vec2> ends{p[0], p[0]};
    for (const Vec2& a : p)
      for (const Vec2& b : p)
        if ((a - b).norm() > (ends.first - ends.second).norm()) ends = {a, b};
    EXPECT_NEAR((ends.first - ends.second).norm(), kLength, 1e-9) << "fracture " << fracture;
    centres.push_back(0.5 * (ends.first + ends.second));
  }
  return centres;
}

TEST(rev_dfn_source, RealizationsDifferAndTheSeedReproducesThem) {
  const flow::RevStudy a = read_study(study_yaml(7));
  const flow::RevStudy b = read_study(study_yaml(7));
  const flow::RevStudy c = read_study(study_yaml(8));
  ASSERT_TRUE(a.source && b.source && c.source);
  EXPECT_EQ(a.config.realizations, 3);
  EXPECT_NE(a.source->describe().find("1 families"), std::string::npos) << a.source->describe();
  const FractureGraph a0 = whole_network(*a.source, 0), a1 = whole_network(*a.source, 1);
  EXPECT_GT(a0.n_segments(), 0);
  EXPECT_NE(a0.nodes, a1.nodes);
  EXPECT_EQ(a1.nodes, whole_network(*b.source, 1).nodes);  // same seed, other source
  EXPECT_NE(a1.nodes, whole_network(*c.source, 1).nodes);
  // A square of the study is a clipped, rotated view of the same network.
  EXPECT_EQ(a.source->domain(2, 8, 0.5).nodes, b.source->domain(2, 8, 0.5).nodes);
}

TEST(rev_dfn_source, FractureCountMatchesP20) {
  // Centres in the region form a Poisson process of intensity P20: their
  // number has mean P20 A and standard deviation sqrt(P20 A) (20 for
  // A = 400 m^2); 4 sigma fails a correct generator with probability 6e-5.
  const flow::RevStudy study = read_study(study_yaml(3));
  const double mean = kP20 * kRegion * kRegion;
  for (int r = 0; r < 3; ++r) {
    int inside = 0;
    for (const Vec2& c : fracture_centres(whole_network(*study.source, r)))
      inside += std::abs(c.x()) < kRegion / 2 && std::abs(c.y()) < kRegion / 2;
    EXPECT_NEAR(inside, mean, 4 * std::sqrt(mean)) << "realization " << r;
  }
}

TEST(rev_dfn_source, RealizationZeroIsTheRockMassDfn) {
  // docs/flow.md: realization 0 draws family f from the rock mass's stream
  // (seed, 0x10000 + f), so it is the scene's DFN over the same domain.
  const flow::RevStudy study = read_study(study_yaml(5));
  DfnFamilySpec spec;
  spec.density_kind = DfnFamilySpec::Density::P20;
  spec.density = kP20;
  spec.orientation.type = DistributionSpec::Type::Uniform;
  spec.length.value = kLength;
  spec.aperture.value = 1e-4;
  Box region;
  region.extend(Vec2(5 - kRegion / 2, -3 - kRegion / 2));
  region.extend(Vec2(5 + kRegion / 2, -3 + kRegion / 2));
  Rng rng(5, 0x10000);
  const std::vector<DfnFracture> expected = generate_dfn_family(spec, region, rng);
  const std::vector<Vec2> centres = fracture_centres(whole_network(*study.source, 0));
  ASSERT_EQ(centres.size(), expected.size());
  std::set<std::pair<long, long>> drawn;  // centres to 1e-6 m, in the study's frame
  for (const Vec2& c : centres) drawn.insert({std::lround(c.x() * 1e6), std::lround(c.y() * 1e6)});
  for (const DfnFracture& f : expected)
    EXPECT_TRUE(drawn.count(
        {std::lround((f.centre.x() - 5) * 1e6), std::lround((f.centre.y() + 3) * 1e6)}));
}

TEST(rev_dfn_source, BadInputNamesTheKey) {
  std::string m = study_error(study_yaml(1, "        joint: rough\n"));
  EXPECT_NE(m.find("study.yaml:14:16: network.dfn.families[0].joint: found 'rough'; expected no "
                   "joint"),
            std::string::npos)
      << m;
  m = study_error(study_yaml(1, "        densty: {p21: 1}\n"));
  EXPECT_NE(m.find("study.yaml:14:9: network.dfn.families[0].densty: unknown key 'densty' (did "
                   "you mean 'density'?)"),
            std::string::npos)
      << m;
  m = study_error(
      "network: {type: dfn, dfn: {families: [{name: a, density: {p21: 0}, orientation: 0, "
      "length: 1}]}}\nsizes: [1]\n");
  EXPECT_NE(m.find("network.dfn.region: key is missing; expected"), std::string::npos) << m;
  EXPECT_NE(m.find("network.dfn.families[0].density.p21: found '0'"), std::string::npos) << m;
  m = study_error(
      "network: {type: dfn, dfn: {region: 1 km, families: [{name: a, density: {p20: "
      "10}, orientation: 0, length: 1}]}}\nsizes: [1]\n");
  EXPECT_NE(m.find("network.dfn: found 1e+07 fractures expected per realization"),
            std::string::npos)
      << m;
}

TEST(rev_dfn_source, DocumentationListsEveryDfnKey) {
  std::ifstream in(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "flow.md");
  ASSERT_TRUE(in) << "docs/flow.md not found";
  std::stringstream text;
  text << in.rdbuf();
  for (const std::string& key : rev_dfn_study_keys())
    EXPECT_NE(text.str().find("| `" + key + "` |"), std::string::npos)
        << "docs/flow.md does not document the REV study key `" << key << "`";
}

}  // namespace
}  // namespace fissure
