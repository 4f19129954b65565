// monitors.csv (core/io/monitor_writer): header, exact values (17 significant
// digits read back to the same double), one flushed row per call.
#include <gtest/gtest.h>

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
  // "still" is fixed in space: no motion, no block stress.
  EXPECT_EQ((std::vector<double>(row.begin() + 10, row.end())),
            (std::vector<double>{-1, 5, 0, 0, 0, 0, 0, 0, 0}));
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
