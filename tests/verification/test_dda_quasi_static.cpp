// coupling.quasi_static (coupling/splitting.h, docs/scene-reference.md
// section 8): the mechanics brought to rest at every update in pseudo-time.
// A block on a fixed base under gravity and a point load ramped over 100 s,
// run quasi-statically in four coupling steps of 25 s, must end where a
// static DDA run (k01 = 0) under the full load comes to rest, and be at
// rest after each update. The static equilibrium is unique here (both
// contacts closed, locked), so the two differ only by the motion left when
// each run stops (measured: 6e-5 of the 9e-5 m displacement); evaluating
// the load at the start of the last span instead of its end would differ
// by 25 %.
#include <gtest/gtest.h>

#include <string>

#include "coupling/process_registry.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

const std::string kScene = R"(physics: [mechanics]
gravity: [0, -9.81]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: bedding, friction_angle: 30}
blocks:
  - {name: base, vertices: [[0, 0], [10, 0], [10, 1], [0, 1]], fixed: true}
  - {name: top, vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]}
monitors:
  - {name: top, point: [5, 1.5]}
mechanics:
  dda: {time_step: 5 ms, velocity_carry_over: 0}
)";

Vec2 centroid_displacement(const RockMass& state) {
  const Block& b = state.blocks[1];
  Vec2 d = Vec2::Zero();
  for (std::size_t k = 0; k < b.polygon.vertices.size(); ++k)
    d += b.polygon.vertices[k] - b.initial_vertices[k];
  return d / static_cast<double>(b.polygon.vertices.size());
}

TEST(DdaQuasiStatic, EndsAtTheStaticEquilibriumOfTheFinalLoad) {
  const Scene quasi_static = read_scene_text(
      kScene +
          "point_loads:\n"
          "  - {point: [5, 2], force: [2 MN, -20 MN], history: [[0, 0], [100, 1]]}\n"
          "coupling:\n  quasi_static: {processes: [mechanics], max_speed: 1e-9 m/s, max_steps: 2000}\n"
          "time: {end: 100 s}\noutput: {interval: 25 s}\n",
      "quasi_static.yaml");
  const RunResult q = run_scene(quasi_static, "quasi_static");
  ASSERT_EQ(q.summary.status, "completed") << q.summary.message;
  EXPECT_DOUBLE_EQ(q.state.time, 100);

  const Scene statics =
      read_scene_text(kScene +
                          "point_loads:\n  - {point: [5, 2], force: [2 MN, -20 MN]}\n"
                          "time: {end: 2 s}\n",
                      "static.yaml");
  const RunResult s = run_scene(statics, "static");
  ASSERT_EQ(s.summary.status, "completed") << s.summary.message;

  const Vec2 dq = centroid_displacement(q.state), ds = centroid_displacement(s.state);
  ASSERT_GT(ds.norm(), 1e-6) << "the load moves the block measurably";
  EXPECT_LT((dq - ds).norm(), 1e-3 * ds.norm())
      << "quasi-static " << dq.transpose() << ", static " << ds.transpose();
  for (const Block& b : q.state.blocks) EXPECT_EQ(b.velocity.norm(), 0.0);
}

}  // namespace
}  // namespace fissure::testing
