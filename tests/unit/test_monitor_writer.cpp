// monitors.csv (core/io/monitor_writer): header, exact values (17 significant
// digits read back to the same double), one flushed row per call.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <filesystem>
#include <sstream>

#include "core/base/errors.h"
#include "core/io/monitor_writer.h"
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
  return fs::path(fissure::testing::scratch_dir("monitor_writer")) / "monitors.csv";
}

}  // namespace

TEST(monitor_writer, HeaderListsEveryMonitorsMechanicsColumns) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, output_test_monitors(), parts.monitors(true, false));
  const auto l = text_lines(file);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0],
            "t,top.x,top.y,top.ux,top.uy,top.vx,top.vy,top.sxx,top.syy,top.sxy,"
            "still.x,still.y,still.ux,still.uy,still.vx,still.vy,still.sxx,still.syy,still.sxy");
}

TEST(monitor_writer, RowsHoldExactValuesAndAreFlushedAtOnce) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, output_test_monitors(), parts.monitors(true, false));
  RockMass s = output_test_state();
  for (int k = 0; k < 3; ++k) {
    set_output_test_frame(s, k);
    writer.write_row(s, 0.1 * k);
    EXPECT_EQ(text_lines(file).size(), static_cast<std::size_t>(k + 2));  // visible before close
  }
  const auto l = text_lines(file);
  // 0.1 needs 17 digits to read back as the same double.
  EXPECT_EQ(l[2].substr(0, l[2].find(',')), "0.10000000000000001");
  const std::vector<double> row = csv_numbers(l[3]);
  ASSERT_EQ(row.size(), 19u);
  EXPECT_EQ(row[0], 0.1 * 2);
  // "top" rides on the ring: moved by 2 (0.0625, 0.5) from (3, 2.75).
  EXPECT_EQ(row[1], 3.125);
  EXPECT_EQ(row[2], 3.75);
  EXPECT_EQ(row[3], 0.125);
  EXPECT_EQ(row[4], 1.0);
  // Ring velocity at r = (0, 0.75) from its centroid: (0.5 - 0.25 * 0.75, 0).
  EXPECT_DOUBLE_EQ(row[5], 0.3125);
  EXPECT_NEAR(row[6], 0.0, 1e-15);
  EXPECT_EQ(row[7], -3e6 - 2);
  EXPECT_EQ(row[8], 5e5);
  EXPECT_EQ(row[9], 202);
  // "still" is fixed in space: where it is, and no block's motion or stress
  // (empty cells: a continuum around the blocks may watch it).
  EXPECT_EQ(row[10], -1);
  EXPECT_EQ(row[11], 5);
  for (std::size_t c = 12; c < row.size(); ++c) EXPECT_TRUE(std::isnan(row[c])) << c;
}

namespace {
/// A source of fixed values per point, NaN where it does not watch.
class Fixed final : public MonitorSource {
 public:
  Fixed(std::vector<MonitorColumn> columns, std::vector<std::vector<double>> per_point)
      : columns_(std::move(columns)), per_point_(std::move(per_point)) {}
  std::vector<MonitorColumn> columns() const override { return columns_; }
  void values(const RockMass&, int point, std::span<double> out) const override {
    std::copy(per_point_[point].begin(), per_point_[point].end(), out.begin());
  }

 private:
  std::vector<MonitorColumn> columns_;
  std::vector<std::vector<double>> per_point_;
};
}  // namespace

// Two processes watching the same quantity (blocks in a continuum): one
// column each name, the first finite value in the processes' order.
TEST(monitor_writer, SameNamedColumnsAreOneTakingTheFirstValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Fixed blocks({{"ux", 0}, {"sxx", 3}}, {{1, 10}, {nan, nan}});
  const Fixed continuum({{"ux", 0}, {"p", 1}, {"sxx", 3}}, {{nan, nan, nan}, {2, 7, 20}});
  const MonitorLayout layout({&blocks, &continuum});
  ASSERT_EQ(layout.columns().size(), 3u);
  EXPECT_EQ(layout.columns()[0].name, "ux");
  EXPECT_EQ(layout.columns()[1].name, "p");
  EXPECT_EQ(layout.columns()[2].name, "sxx");
  const RockMass state;
  EXPECT_EQ(layout.values(state, 0)[0], 1);  // in a block
  EXPECT_EQ(layout.values(state, 0)[2], 10);
  EXPECT_TRUE(std::isnan(layout.values(state, 0)[1]));
  EXPECT_EQ(layout.values(state, 1), (std::vector<double>{2, 7, 20}));  // in the continuum
}

TEST(monitor_writer, WithoutMechanicsOnlyTimeIsWritten) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, output_test_monitors(), parts.monitors(false, false));
  writer.write_row(output_test_state(), 1.5);
  EXPECT_EQ(text_lines(file), (std::vector<std::string>{"t", "1.5"}));
}

TEST(monitor_writer, NoMonitorsGivesATimeColumn) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, {}, parts.monitors(true, false));
  writer.write_row(output_test_state(), 0);
  writer.write_row(output_test_state(), 2);
  EXPECT_EQ(text_lines(file), (std::vector<std::string>{"t", "0", "2"}));
}

TEST(monitor_writer, NamesThatNeedQuotingAreQuoted) {
  const fs::path file = fresh_file();
  Monitor m;
  m.name = "a,\"b\"";
  OutputParts parts;
  MonitorWriter writer(file, {m}, parts.monitors(true, false));
  EXPECT_EQ(text_lines(file)[0].substr(0, 13), "t,\"a,\"\"b\"\".x\"");
}

TEST(monitor_writer, StateWithFewerPointsThanMonitorsIsAnError) {
  const fs::path file = fresh_file();
  OutputParts parts;
  MonitorWriter writer(file, output_test_monitors(), parts.monitors(true, false));
  RockMass s = output_test_state();
  s.points.resize(1);
  EXPECT_THROW(writer.write_row(s, 0), IoError);
}

TEST(monitor_writer, UnwritableFileIsAnIoErrorNamingIt) {
  const fs::path file = fs::path(FISSURE_BINARY_DIR) / "test-output" / "no" / "such" / "m.csv";
  try {
    OutputParts parts;
    MonitorWriter writer(file, {}, parts.monitors(true, false));
    FAIL() << "no error for a missing folder";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}
