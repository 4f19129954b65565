// verification.md (f) with heated water: the parallel-plate fracture (L = 1 m,
// e = 100 um, dp = 0.1 MPa) whose water is at temperature T, as a thermal
// process would write it on the field fracture_fluid_temperature
// (rockmass/fields/fracture_temperature.h). The cubic law then carries
// q(T) = e^3 dp / (12 mu(T) L) with mu(T) of Kestin et al.
// (flow/network/water_viscosity.h): the flux scales by mu(20 C) / mu(T). The
// network is exact for one segment, so the tolerance is round-off, 1e-10.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "flow/cubic_law/cubic_law_process.h"
#include "flow/network/water_viscosity.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fracture_graph.h"
#include "tests/support/flow_networks.h"

namespace fissure::flow {
namespace {

constexpr double kE = 100e-6, kDp = 0.1e6;

Scene parallel_plate() {
  Scene s = testing::trace_flow_scene({{Eigen::Vector2d(-0.5, 0.3), Eigen::Vector2d(1.5, 0.3), kE}},
                                      Vec2(0, 0), Vec2(1, 1));
  FlowBoundaryCondition left, right;
  left.boundary = "left";
  left.value = kDp;
  right.boundary = "right";
  right.value = 0;
  flow_controls(s).conditions = {left, right};
  return s;
}

struct HeatedFracture {
  double flux = 0;
  nlohmann::json statistics;
};

/// The steady flux of the fracture once its water is at `celsius`.
HeatedFracture flux_at(double celsius, const Scene& s = parallel_plate()) {
  RockMass state = RockMass::from_scene(s);
  CubicLawProcess flow(s);
  flow.initialize(state);
  const int segments = state.fields.get(kFractureGraph).n_segments();
  state.fields.get_or_add(kFractureFluidTemperature).assign(segments, celsius);
  EXPECT_EQ(flow.advance(state, 0, 1).status, StepReport::Status::Ok);
  const FractureFlowState& f = state.fields.get(kFractureFlow);
  EXPECT_EQ(f.flux.size(), 1u);
  return {f.flux.at(0), flow.statistics()};
}

TEST(FlowViscosityTemperature, FluxScalesWithTheViscosityRatio) {
  const double q20 = kE * kE * kE * kDp / (12 * kWaterViscosityAt20C);  // 8.3200e-6 m^2/s
  for (const double t : {5.0, 20.0, 50.0, 80.0, 99.0}) {
    SCOPED_TRACE(t);
    const HeatedFracture h = flux_at(t);
    const double expected = q20 * kWaterViscosityAt20C / water_viscosity(t);
    EXPECT_NEAR(h.flux, expected, 1e-10 * expected);
    EXPECT_EQ(h.statistics["viscosity"]["boiling_segments"], 0);
    EXPECT_FALSE(h.statistics["viscosity"].contains("warning"));
  }
  // 80 C water flows 2.82 times as fast as at 20 C (mu 0.355 against 1.0016 mPa s).
  EXPECT_NEAR(flux_at(80).flux / flux_at(20).flux, 2.8216, 1e-4);
}

TEST(FlowViscosityTemperature, WaterAboveItsBoilingPointIsAWarning) {
  // 120 C boils below 198.7 kPa; the fracture's mean pressure is 50 kPa
  // above the atmosphere: the run goes on with the liquid's viscosity and
  // summary.json says so.
  const HeatedFracture h = flux_at(120);
  EXPECT_NEAR(h.flux, kE * kE * kE * kDp / (12 * water_viscosity(120)), 1e-10 * h.flux);
  const nlohmann::json& v = h.statistics["viscosity"];
  EXPECT_EQ(v["boiling_segments"], 1);
  EXPECT_EQ(v["temperature"]["max"], 120);
  ASSERT_TRUE(v.contains("warning"));
  EXPECT_NE(v["warning"].get<std::string>().find("above its boiling point"), std::string::npos);
  // Below freezing (supercooled): a warning too.
  EXPECT_EQ(flux_at(-5).statistics["viscosity"]["supercooled_segments"], 1);
}

TEST(FlowViscosityTemperature, TemperatureWithoutAViscosityIsAnError) {
  for (const double t : {200.0, -20.0, std::numeric_limits<double>::quiet_NaN()}) {
    SCOPED_TRACE(t);
    const Scene s = parallel_plate();
    RockMass state = RockMass::from_scene(s);
    CubicLawProcess flow(s);
    flow.initialize(state);
    state.fields.get_or_add(kFractureFluidTemperature).assign(1, t);
    try {
      flow.advance(state, 0, 1);
      ADD_FAILURE() << "no error";
    } catch (const DivergenceError& e) {
      EXPECT_NE(std::string(e.what()).find("outside the range of the viscosity correlation"),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("fracture segment 0 at (0.5, 0.3) m"), std::string::npos)
          << e.what();
    }
  }
}

TEST(FlowViscosityTemperature, NoFieldKeepsTheFluidsViscosity) {
  const Scene s = parallel_plate();
  RockMass state = RockMass::from_scene(s);
  CubicLawProcess flow(s);
  flow.initialize(state);
  ASSERT_EQ(flow.advance(state, 0, 1).status, StepReport::Status::Ok);
  const double q = kE * kE * kE * kDp / (12 * flow_controls(s).fluid.viscosity);
  EXPECT_NEAR(state.fields.get(kFractureFlow).flux.at(0), q, 1e-10 * q);
  EXPECT_FALSE(flow.statistics().contains("viscosity"));
}

}  // namespace
}  // namespace fissure::flow
