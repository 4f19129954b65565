// The flow column m.p of monitors.csv (core/io/monitor_writer,
// fracture_pressure; docs/output.md): its place among the other columns, the
// pressure linear along the nearest segment, and NaN with one warning for a
// monitor away from the network.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/io/monitor_writer.h"
#include "flow/cubic_law/fracture_pressure.h"
#include "rockmass/fields/fracture_flow.h"
#include "tests/support/output_parts.h"
#include "tests/support/output_test_state.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fs = std::filesystem;
using namespace fissure;
using namespace fissure::test;

namespace {

/// monitors.csv in this test's own scratch folder.
fs::path fresh_file() {
  return fs::path(fissure::testing::scratch_dir("monitor_pressure")) / "monitors.csv";
}

Monitor monitor(const std::string& name, const Vec2& point) {
  Monitor m;
  m.name = name;
  m.point = point;
  return m;
}

/// An L of two 4 m segments, (0, 0) - (4, 0) - (4, 4), pressures 8, 4 and
/// 0 Pa at its nodes (size 4 m: search distance 4 mm), and a material point
/// per monitor.
RockMass flow_state(const std::vector<Monitor>& monitors) {
  RockMass s;
  FractureGraph& graph = s.fields.get_or_add(kFractureGraph);
  graph.nodes = {{0, 0}, {4, 0}, {4, 4}};
  FractureSegment a, b;
  a.node_a = 0, a.node_b = 1, b.node_a = 2, b.node_b = 1;
  graph.segments = {a, b};
  s.fields.get_or_add(kFractureFlow).pressure = {8, 4, 0};
  for (const Monitor& m : monitors) s.points.push_back(MaterialPoint{-1, m.point, m.point});
  return s;
}

}  // namespace

TEST(monitor_pressure, PComesAfterTheMotionAndBeforeTheStress) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, output_test_monitors(), parts.monitors(true, true));
  EXPECT_EQ(text_lines(file)[0],
            "t,top.x,top.y,top.ux,top.uy,top.vx,top.vy,top.p,top.sxx,top.syy,top.sxy,"
            "still.x,still.y,still.ux,still.uy,still.vx,still.vy,still.p,still.sxx,still.syy,"
            "still.sxy");
}

TEST(monitor_pressure, FlowAloneWritesOnlyP) {
  const fs::path file = fresh_file();
  const std::vector<Monitor> monitors{monitor("a", Vec2(1, 0)), monitor("b", Vec2(4, 3))};
  OutputParts parts;
  MonitorWriter writer(file, monitors, parts.monitors(false, true));
  writer.write_row(flow_state(monitors), 0.5);
  EXPECT_EQ(text_lines(file), (std::vector<std::string>{"t,a.p,b.p", "0.5,7,1"}));
}

TEST(monitor_pressure, LinearAlongTheNearestSegmentWithinTheSearchDistance) {
  const RockMass s = flow_state({});
  const FractureGraph& graph = s.fields.get(kFractureGraph);
  EXPECT_DOUBLE_EQ(pressure_search_distance(graph), 4e-3);
  EXPECT_DOUBLE_EQ(fracture_pressure_at(s, Vec2(1, 0)), 7);
  EXPECT_DOUBLE_EQ(fracture_pressure_at(s, Vec2(3, 0.003)), 5);      // 3 mm off the joint
  EXPECT_DOUBLE_EQ(fracture_pressure_at(s, Vec2(4.002, 1)), 3);      // the second segment
  EXPECT_DOUBLE_EQ(fracture_pressure_at(s, Vec2(-0.003, 0)), 8);     // beyond an end
  EXPECT_DOUBLE_EQ(fracture_pressure_at(s, Vec2(4, 0)), 4);          // a shared node
  EXPECT_TRUE(std::isnan(fracture_pressure_at(s, Vec2(2, 0.005))));  // 5 mm off
  EXPECT_TRUE(std::isnan(fracture_pressure_at(s, Vec2(2, 2))));
  RockMass no_flow = s;
  no_flow.fields.get(kFractureFlow).pressure.clear();
  EXPECT_TRUE(std::isnan(fracture_pressure_at(no_flow, Vec2(1, 0))));
  const SegmentProjection near = nearest_segment(graph, Vec2(4.5, 1));
  EXPECT_EQ(near.segment, 1);
  EXPECT_DOUBLE_EQ(near.s, 0.75);
  EXPECT_DOUBLE_EQ(near.distance, 0.5);
}

TEST(monitor_pressure, AMonitorOffTheNetworkIsNanWithOneWarning) {
  const fs::path file = fresh_file();
  const std::vector<Monitor> monitors{monitor("on", Vec2(2, 0)), monitor("away", Vec2(2, 2))};
  std::vector<std::string> warnings;
  OutputParts parts;
  MonitorWriter writer(file, monitors, parts.monitors(true, true),
                       [&](const std::string& w) { warnings.push_back(w); });
  RockMass s = flow_state(monitors);
  writer.write_row(s, 0);
  s.fields.get(kFractureFlow).pressure = {16, 8, 0};
  writer.write_row(s, 1);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("monitor 'away' at (2, 2) m"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("0.004 m"), std::string::npos) << warnings[0];
  const auto l = text_lines(file);
  ASSERT_EQ(l.size(), 3u);
  const std::vector<double> row = csv_numbers(l[2]);
  ASSERT_EQ(row.size(), 21u);
  EXPECT_EQ(row[7], 12);  // on.p, after on.x .. on.vy
  EXPECT_TRUE(std::isnan(row[17]));
  EXPECT_NE(l[2].find(",,"), std::string::npos);  // missing: an empty cell, never "nan"
  EXPECT_EQ(l[2].find("nan"), std::string::npos);
}
