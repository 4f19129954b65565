// The work of the rock-mass generators is known before it is spent (issue
// 35, item 3; docs/rock-mass.md sections 3.1, 4.1 and 5): a DFN family draws
// only fractures that can reach its domain, however long they are, and the
// block cutter cuts off what lies beyond the domain, so that neither the
// draws nor the cut grow with the lengths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/base/stopwatch.h"
#include "core/geometry/segment_clip.h"
#include "coupling/process_registry.h"
#include "rockmass/block_cutter.h"
#include "rockmass/dfn_generator.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure {
namespace {

constexpr double kSide = 30;  // m, the region of the issue's scene

Box region() {
  Box b;
  b.extend(Vec2(0, 0));
  b.extend(Vec2(kSide, kSide));
  return b;
}

/// P21 = 0.5 /m of fractures `length` (m) long in all directions.
DfnFamilySpec long_family(double length) {
  DfnFamilySpec f;
  f.name = std::string("long");
  f.density_kind = DfnFamilySpec::Density::P21;
  f.density = 0.5;
  f.orientation.type = DistributionSpec::Type::Uniform;
  f.length.value = length;
  f.aperture.value = 1e-4;
  return f;
}

const std::string kLongScene = R"(physics: [mechanics]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: rough, friction_angle: 35, cohesion: 0}
rock_mass:
  domain: [[0, 0], [30, 0], [30, 30], [0, 30]]
  dfn:
    - name: long
      density: {p21: 0.5 1/m}
      orientation: {distribution: uniform}
      length: 1e6 m
mechanics: {}
time:
  end: 0.01
)";

TEST(generator_work, MillionMetreDfnFracturesInA30MetreRegionValidateInWellUnderTenSeconds) {
  // The tester's scene: before, 5e5 fractures were drawn in the region grown
  // by half their length, P20 (30 + 1e6)^2, and a third of them went into
  // the arrangement, crossing each other far outside: more than 5 minutes.
  // The strip window draws P20 W H + P21 (W + H) = 30 of them.
  ASSERT_LT(expected_dfn_fractures(long_family(1e6), region()), 31.0);
  Stopwatch clock;
  const Scene scene = read_scene_text(kLongScene, "long.yaml");
  const double seconds = clock.lap();
  EXPECT_LT(seconds, 10.0);  // about 0.05 s
  const RockMassStatistics& s = scene.sections.get(kRockMassStatistics);
  EXPECT_LT(s.generated_fractures, 100);
  EXPECT_GT(s.cut_fractures, 5);
  EXPECT_GT(scene.blocks.size(), 5u);
}

TEST(generator_work, TheDrawsOfAFamilyDoNotGrowWithItsLengthAndAllReachTheRegion) {
  // Fixed P21: from about the region's size on, the work is at most
  // P20 W H + P21 (W + H), whatever the length (up to the 1e7 m limit).
  const double bound_at_one_metre = expected_dfn_fractures(long_family(1), region());
  for (double length : {1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7}) {
    SCOPED_TRACE(length);
    const DfnFamilySpec f = long_family(length);
    const double expected = expected_dfn_fractures(f, region());
    EXPECT_LE(expected, bound_at_one_metre);
    if (length < 100) continue;
    EXPECT_TRUE(dfn_uses_strips(f, region()));
    EXPECT_LE(expected, f.density / length * kSide * kSide + f.density * 2 * kSide + 1e-9);
    Rng rng(7, 0);
    for (const DfnFracture& fracture : generate_dfn_family(f, region(), rng)) {
      FractureTrace t = fracture.trace(0, -1);
      EXPECT_TRUE(clip_to_box(t.a, t.b, region())) << "a fracture that misses the region";
    }
  }
}

/// The blocks' areas and the graph's nodes, sorted.
std::vector<double> block_areas(const CutResult& cut) {
  std::vector<double> a;
  for (const CutBlock& b : cut.blocks) a.push_back(section_properties(b.polygon).area);
  std::sort(a.begin(), a.end());
  return a;
}

std::vector<std::pair<double, double>> nodes(const CutResult& cut) {
  std::vector<std::pair<double, double>> n;
  for (const Vec2& p : cut.graph.nodes) n.emplace_back(p.x(), p.y());
  std::sort(n.begin(), n.end());
  return n;
}

TEST(generator_work, LongTracesCutWhatTheirPiecesNearTheDomainCut) {
  // Three traces across a 10 m box, once 2e6 m long (crossing each other
  // far outside too) and once 20 m long (within one extent of the box, kept
  // as they are): the same blocks and fracture-graph nodes, to the round-off
  // of the cut-off ends (1e-10 m on a 1e6 m trace).
  CutInput in;
  in.domain = {Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)};
  in.merge_tolerance = 1e-4;
  const Vec2 centre[] = {Vec2(5, 5), Vec2(3, 7), Vec2(6.1, 2.3)};
  const Vec2 direction[] = {Vec2(1, 0.3).normalized(), Vec2(0.2, -1).normalized(),
                            Vec2(-0.7, 1).normalized()};
  auto traces = [&](double half) {
    std::vector<FractureTrace> t;
    for (int k = 0; k < 3; ++k)
      t.push_back({centre[k] - half * direction[k], centre[k] + half * direction[k], 0, -1, 1e-4});
    return t;
  };
  in.traces = traces(1e6);
  const CutResult cut_long = cut_blocks(in);
  in.traces = traces(10);
  const CutResult cut_short = cut_blocks(in);
  ASSERT_EQ(cut_long.blocks.size(), cut_short.blocks.size());
  ASSERT_EQ(cut_long.graph.nodes.size(), cut_short.graph.nodes.size());
  const std::vector<double> a = block_areas(cut_long), b = block_areas(cut_short);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-8);
  const auto p = nodes(cut_long), q = nodes(cut_short);
  for (size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p[i].first, q[i].first, 1e-9);
    EXPECT_NEAR(p[i].second, q[i].second, 1e-9);
  }
}

}  // namespace
}  // namespace fissure
