// The ground motion of dynamic DDA (mechanics/dda/ground_motion.h,
// ground_motion_file.h; docs/dda.md section 10): exact integration of the
// record between its samples, the baseline correction, the record formats
// and their located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "mechanics/dda/ground_motion.h"
#include "mechanics/dda/ground_motion_file.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/run_scene.h"

namespace fissure::dda {
namespace {

GroundMotionRecord record(MotionQuantity q, const std::vector<double>& t,
                          const std::vector<double>& x) {
  GroundMotionRecord r;
  r.quantity = q;
  r.time = t;
  for (const double v : x) r.values.emplace_back(v, -2 * v);
  return r;
}

TEST(GroundMotion, AnAccelerationLinearInTimeIsIntegratedExactly) {
  // a = c t sampled every 0.5 s: v = c t^2 / 2, u = c t^3 / 6 at any time,
  // here from the scene time start = 1 s on.
  const double c = 3;
  std::vector<double> t, a;
  for (int k = 0; k <= 4; ++k) t.push_back(0.5 * k), a.push_back(c * 0.5 * k);
  const GroundMotion g(record(MotionQuantity::Acceleration, t, a), 1.0, false);
  for (const double tau : {0.0, 0.37, 1.0, 1.234, 2.0}) {
    EXPECT_NEAR(g.acceleration(1 + tau).x(), c * tau, 1e-13);
    EXPECT_NEAR(g.velocity(1 + tau).x(), c * tau * tau / 2, 1e-13);
    EXPECT_NEAR(g.displacement(1 + tau).x(), c * tau * tau * tau / 6, 1e-13);
    EXPECT_NEAR(g.displacement(1 + tau).y(), -2 * c * tau * tau * tau / 6, 1e-13);
  }
  // At rest before the record; no acceleration after it, its end velocity kept.
  EXPECT_EQ(g.displacement(0.5).x(), 0);
  EXPECT_EQ(g.velocity(0.99).x(), 0);
  EXPECT_EQ(g.acceleration(3.5).x(), 0);
  EXPECT_NEAR(g.velocity(3.5).x(), c * 2, 1e-13);
  EXPECT_NEAR(g.displacement(3.5).x(), c * 8 / 6 + c * 2 * 0.5, 1e-12);
}

TEST(GroundMotion, VelocityAndDisplacementRecordsAreLinearBetweenSamples) {
  const std::vector<double> t = {0, 1, 3};
  const GroundMotion v(record(MotionQuantity::Velocity, t, {0, 2, -2}), 0, true);
  EXPECT_NEAR(v.velocity(0.5).x(), 1, 1e-15);
  EXPECT_NEAR(v.displacement(1).x(), 1, 1e-15);  // int_0^1 2 t dt
  EXPECT_NEAR(v.displacement(3).x(), 1, 1e-15);  // + int of 2 -> -2 over 2 s
  EXPECT_NEAR(v.acceleration(2).x(), -2, 1e-15);
  const GroundMotion u(record(MotionQuantity::Displacement, t, {5, 6, 4}), 0, true);
  EXPECT_NEAR(u.displacement(0).x(), 0, 1e-15);  // the base starts where it is
  EXPECT_NEAR(u.displacement(2).x(), 0, 1e-15);
  EXPECT_NEAR(u.velocity(0.5).x(), 1, 1e-15);
  EXPECT_NEAR(u.displacement(10).x(), -1, 1e-15);  // held after the record
}

TEST(GroundMotion, TheBaselineCorrectionRemovesAnOffsetAndItsDrift) {
  // 10 s of shaking at 1 Hz whose velocity sin(2 pi t) starts and ends at
  // rest, with an instrument offset of 0.05 m/s^2: integrated as read, the
  // ground ends at 0.5 m/s and 2.5 m away.
  const double w = 2 * std::numbers::pi;
  std::vector<double> t, a;
  for (int k = 0; k <= 1000; ++k) {
    t.push_back(0.01 * k);
    a.push_back(w * std::cos(w * t.back()) + 0.05);
  }
  const GroundMotion raw(record(MotionQuantity::Acceleration, t, a), 0, false);
  const GroundMotion corrected(record(MotionQuantity::Acceleration, t, a), 0, true);
  EXPECT_NEAR(raw.velocity(10).x(), 0.5, 1e-6);
  EXPECT_NEAR(raw.displacement(10).x(), 2.5, 1e-4);
  // The corrected ground ends at rest; the shaking's own velocity has no
  // trend, so what the quadratic takes besides the offset is small and the
  // drift is gone.
  EXPECT_NEAR(corrected.velocity(10).x(), 0, 1e-12);
  EXPECT_LT(std::abs(corrected.displacement(10).x()), 0.05);
  const nlohmann::json report = corrected.report();
  EXPECT_TRUE(report["baseline_correction"]["applied"].get<bool>());
  EXPECT_NEAR(report["baseline_correction"]["uncorrected_end_velocity"][0].get<double>(), 0.5,
              1e-6);
  // A pure offset is a velocity b1 t: the correction removes it exactly.
  const GroundMotion offset(
      record(MotionQuantity::Acceleration, t, std::vector<double>(t.size(), 0.05)), 0, true);
  EXPECT_NEAR(offset.velocity(10).x(), 0, 1e-12);
  EXPECT_NEAR(offset.acceleration(3.3).x(), 0, 1e-12);
}

/// A file with `text` in a scratch folder (emptied once per test program).
std::string written(const std::string& name, const std::string& text) {
  static const std::string dir = testing::scratch_dir("ground_motion_files");
  const std::string file = dir + "/" + name;
  std::ofstream(file) << text;
  return file;
}

TEST(GroundMotionFile, ReadsCsvColumnsAndPeerAt2) {
  const std::string csv = written("r.csv", "time,ax,ay\n0,1,2\n0.01,3,4\n");
  RecordColumns c = read_record_columns(csv, RecordFormat::Csv, {}, {});
  EXPECT_EQ(c.time, (std::vector<double>{0, 0.01}));
  EXPECT_EQ(c.x, (std::vector<double>{1, 3}));
  EXPECT_EQ(c.y, (std::vector<double>{2, 4}));
  c = read_record_columns(csv, RecordFormat::Csv, {"ay", 0, false}, {"", 0, true});
  EXPECT_EQ(c.x, (std::vector<double>{2, 4}));
  EXPECT_TRUE(c.y.empty());

  const std::string columns = written("r.txt", "# t a\n0  0.5\n\n0.02 -0.5 # peak\n");
  c = read_record_columns(columns, format_of(columns), {}, {});
  EXPECT_EQ(c.x, (std::vector<double>{0.5, -0.5}));
  EXPECT_TRUE(c.y.empty());

  for (const std::string header : {"NPTS=    3, DT=   .0050 SEC", "3   .0050   NPTS, DT"}) {
    const std::string at2 = written("r.AT2",
                                    "PEER NGA STRONG MOTION DATABASE RECORD\nX\n"
                                    "ACCELERATION TIME SERIES IN UNITS OF G\n" +
                                        header + "\n .1E-02 -.2E-02\n  .3E-02\n");
    EXPECT_EQ(format_of(at2), RecordFormat::PeerAt2);
    c = read_peer_at2(at2);
    EXPECT_EQ(c.time, (std::vector<double>{0, 0.005, 0.01}));
    EXPECT_EQ(c.x, (std::vector<double>{1e-3, -2e-3, 3e-3}));
  }
}

/// The message and place of the error reading `text` as `format`.
std::string problem(const std::string& name, const std::string& text, RecordFormat format) {
  const std::string file = written(name, text);
  try {
    if (format == RecordFormat::PeerAt2)
      read_peer_at2(file);
    else
      read_record_columns(file, format, {}, {});
  } catch (const RecordFileError& e) {
    return std::to_string(e.where().line) + ":" + std::to_string(e.where().column) + ": " +
           e.what();
  }
  return "no error";
}

TEST(GroundMotionFile, NamesTheLineAndColumnOfAProblem) {
  EXPECT_EQ(problem("a.csv", "t,a\n0,1\n0,2\n", RecordFormat::Csv),
            "3:1: found the time 0 s after 0 s; expected times that increase strictly");
  EXPECT_EQ(problem("b.csv", "t,a\n0,1\n0.1, 2x\n", RecordFormat::Csv),
            "3:6: found '2x'; expected a value of the record (a number)");
  EXPECT_EQ(problem("c.txt", "0 1 2\n0.1 2\n", RecordFormat::Columns),
            "2:1: found 2 values; expected 3 as in the first row");
  EXPECT_EQ(problem("d.txt", "-1 1\n0 2\n", RecordFormat::Columns).substr(0, 28),
            "1:1: found the time -1 s; ex");
  EXPECT_EQ(problem("e.txt", "0 1\n", RecordFormat::Columns),
            "1:1: found 1 samples; expected a record of at least two");
  EXPECT_EQ(problem("f.at2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n1 2\n", RecordFormat::PeerAt2),
            "5:1: found 2 values; expected NPTS = 3");
  EXPECT_EQ(problem("g.at2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n1 2 3 nan\n", RecordFormat::PeerAt2),
            "5:7: found more values than NPTS = 3");
}

TEST(GroundMotionFile, ASceneNamesTheRecordsProblemWhereItIs) {
  const std::string dir = testing::scratch_dir("ground_motion_scene");
  std::ofstream(dir + "/quake.csv") << "t,a\n0,0\n0.01,0.1\n0.02,inf\n";
  const std::string text = R"(name: quake
physics: [mechanics]
materials: [{name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}]
joints: [{name: j, friction_angle: 30}]
blocks:
  - {name: base, vertices: [[0, -1], [4, -1], [4, 0], [0, 0]], fixed: true}
  - {name: block, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}
mechanics:
  ground_motion: {file: quake.csv, unit: g}
time: {end: 1}
)";
  const std::string scene = dir + "/quake.yaml";
  const std::string inf = testing::parse_error(text, scene);
  testing::expect_contains(inf, "mechanics.ground_motion.file: ");
  testing::expect_contains(inf, "quake.csv:4:6: found 'inf'");
  testing::expect_contains(inf, "a finite number");
  // A unit of the wrong kind is refused, naming the key.
  std::ofstream(dir + "/quake.csv") << "t,a\n0,0\n0.01,0.1\n";
  std::string wrong = text;
  wrong.replace(wrong.find("unit: g"), 7, "unit: m/s");
  testing::expect_contains(testing::parse_error(wrong, scene), "mechanics.ground_motion.unit");
  // `x: none` is refused, and the record is still read safely (it was read
  // without a horizontal column, out of bounds).
  std::string no_x = text;
  no_x.replace(no_x.find("unit: g"), 7, "unit: g, x: none");
  const std::string none = testing::parse_error(no_x, scene);
  testing::expect_contains(none, "mechanics.ground_motion.x");
  testing::expect_contains(none, "only `y` may be none");
  // A record that is not there is named with the folder it was looked for in.
  std::string missing = text;
  missing.replace(missing.find("file: quake.csv"), 15, "file: records/quake.csv");
  const std::string absent = testing::parse_error(missing, scene);
  testing::expect_contains(absent, "mechanics.ground_motion.file");
  testing::expect_contains(absent, "found no file " + dir +
                                       "/records/quake.csv (the path is relative to the scene "
                                       "file's folder); expected a ground-motion record");
}

}  // namespace
}  // namespace fissure::dda
