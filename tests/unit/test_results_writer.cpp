// results.h5 + results.xdmf (core/io/results_writer): the fixed mesh, every
// frame's fields read back exactly with the HDF5 C API, and an XDMF index whose
// every reference names a dataset of the right shape and type.
//
// The 4-frame output of FourFrames is kept in
// <build>/test-output/results_writer/FourFrames for scripts/check_xdmf_paraview.py.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/base/errors.h"
#include "core/geometry/polygon.h"
#include "core/io/results_writer.h"
#include "tests/support/output_parts.h"
#include "tests/support/output_test_state.h"
#include "tests/support/results_file_reader.h"

namespace fs = std::filesystem;
using namespace fissure;
using namespace fissure::test;

namespace {

fs::path fresh_output_dir() {
  const fs::path dir = fs::path(FISSURE_BINARY_DIR) / "test-output" / "results_writer" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Writes frames 0 .. n-1 of the test motion.
void write_frames(const fs::path& dir, int n, TimeUnit time_unit = {}) {
  OutputParts parts;
  ResultsWriter writer(dir, parts.results(), time_unit);
  RockMass s = output_test_state();
  for (int k = 0; k < n; ++k) {
    set_output_test_frame(s, k);
    writer.write_frame(s, s.time);
    EXPECT_EQ(writer.n_frames(), k + 1);
  }
}

std::string frame(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%06d", k);
  return name;
}

}  // namespace

TEST(results_writer, MeshHasBlocksLoopsAndACoveringTriangulation) {
  const fs::path dir = fresh_output_dir();
  write_frames(dir, 1);
  H5Reader h5(dir / "results.h5");

  EXPECT_EQ(h5.strings("/mesh/block_names"), (std::vector<std::string>{"base", "ell", "ring"}));
  EXPECT_EQ(h5.ints("/mesh/block_fixed"), (std::vector<int>{1, 0, 0}));
  EXPECT_EQ(h5.ints("/mesh/block_vertex_offsets"), (std::vector<int>{0, 4, 10, 18}));
  EXPECT_EQ(h5.ints("/mesh/block_loop_offsets"), (std::vector<int>{0, 1, 2, 4}));
  EXPECT_EQ(h5.ints("/mesh/loop_offsets"), (std::vector<int>{0, 4, 10, 14, 18}));
  const std::vector<double> x0 = h5.doubles("/mesh/initial_vertices");
  ASSERT_EQ(h5.shape("/mesh/initial_vertices"), (std::vector<hsize_t>{18, 2}));
  EXPECT_EQ(x0[2 * 14], 2.5);  // first hole vertex (2.5, 1.5)
  EXPECT_EQ(x0[2 * 14 + 1], 1.5);

  // n - 2 + 2 holes triangles per block: 2 (base) + 4 (L) + 8 (ring).
  const std::vector<int> tri = h5.ints("/mesh/triangles");
  const std::vector<int> tri_block = h5.ints("/mesh/triangle_block");
  ASSERT_EQ(h5.shape("/mesh/triangles"), (std::vector<hsize_t>{14, 3}));
  ASSERT_EQ(tri_block.size(), 14u);
  const std::vector<int> offsets{0, 4, 10, 18};
  std::vector<double> area(3, 0.0);
  for (std::size_t t = 0; t < tri_block.size(); ++t) {
    const int b = tri_block[t];
    Vec2 p[3];
    for (int c = 0; c < 3; ++c) {
      const int v = tri[3 * t + c];
      ASSERT_GE(v, offsets[b]);
      ASSERT_LT(v, offsets[b + 1]);
      p[c] = Vec2(x0[2 * v], x0[2 * v + 1]);
    }
    const double a = orient(p[0], p[1], p[2]) / 2;
    EXPECT_GT(a, 0) << "triangle " << t << " is not counter-clockwise";
    area[b] += a;
  }
  // The triangles cover each block exactly: the L (2.5) and the ring without its hole (3).
  EXPECT_NEAR(area[0], 4.0, 1e-12);
  EXPECT_NEAR(area[1], 2.5, 1e-12);
  EXPECT_NEAR(area[2], 3.0, 1e-12);
}

TEST(results_writer, FourFrames) {
  const fs::path dir = fresh_output_dir();
  write_frames(dir, 4);
  H5Reader h5(dir / "results.h5");

  const std::vector<std::string> frames = h5.members("/frames");
  ASSERT_EQ(frames, (std::vector<std::string>{"000000", "000001", "000002", "000003"}));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(h5.double_attribute(frame(k), "time"), 0.25 * k);

  // Frame 3: L vertex 2 (global 4 + 2) started at (2, 1.5) and moved by 3 (0.125, -0.25).
  const std::string f3 = frame(3);
  const std::vector<double> x = h5.doubles(f3 + "/vertices");
  const std::vector<double> u = h5.doubles(f3 + "/displacement");
  ASSERT_EQ(h5.shape(f3 + "/vertices"), (std::vector<hsize_t>{18, 2}));
  ASSERT_EQ(h5.shape(f3 + "/displacement"), (std::vector<hsize_t>{18, 3}));
  EXPECT_EQ(x[2 * 6], 2.375);
  EXPECT_EQ(x[2 * 6 + 1], 0.75);
  EXPECT_EQ(u[3 * 6], 0.375);
  EXPECT_EQ(u[3 * 6 + 1], -0.75);
  EXPECT_EQ(u[3 * 6 + 2], 0.0);
  // The fixed base does not move.
  for (int i = 0; i < 3 * 4; ++i) EXPECT_EQ(u[i], 0.0);

  // Velocity: the L translates at (1, -2); ring corner (4, 3) is at r = (1, 1)
  // from the centroid, so it moves at (0.5 - 0.25 * 1, 0.25 * 1).
  const std::vector<double> v = h5.doubles(f3 + "/velocity");
  ASSERT_EQ(h5.shape(f3 + "/velocity"), (std::vector<hsize_t>{18, 3}));
  EXPECT_EQ(v[3 * 6], 1.0);
  EXPECT_EQ(v[3 * 6 + 1], -2.0);
  EXPECT_DOUBLE_EQ(v[3 * 12], 0.25);
  EXPECT_DOUBLE_EQ(v[3 * 12 + 1], 0.25);
  EXPECT_EQ(v[3 * 12 + 2], 0.0);

  // Cell data: every triangle carries its block's stress and id.
  const std::vector<int> tri_block = h5.ints("/mesh/triangle_block");
  const std::vector<double> sxx = h5.doubles(f3 + "/sxx");
  const std::vector<double> syy = h5.doubles(f3 + "/syy");
  const std::vector<double> sxy = h5.doubles(f3 + "/sxy");
  EXPECT_EQ(h5.ints(f3 + "/block_id"), tri_block);
  ASSERT_EQ(sxx.size(), tri_block.size());
  for (std::size_t t = 0; t < tri_block.size(); ++t) {
    const int b = tri_block[t];
    EXPECT_EQ(sxx[t], -1e6 * (b + 1) - 3);
    EXPECT_EQ(syy[t], 7.5e5);
    EXPECT_EQ(sxy[t], 100.0 * b + 3);
  }

  // Contacts: none in frame 0, two in frame 2.
  EXPECT_FALSE(h5.exists(frame(0) + "/contacts"));
  const std::string c2 = frame(2) + "/contacts";
  ASSERT_EQ(h5.shape(c2 + "/points"), (std::vector<hsize_t>{2, 2}));
  ASSERT_EQ(h5.shape(c2 + "/normal"), (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(h5.doubles(c2 + "/points"), (std::vector<double>{0.5, 1, 3, 1}));
  EXPECT_EQ(h5.doubles(c2 + "/normal"), (std::vector<double>{0, 1, 0, 0, 1, 0}));
  EXPECT_EQ(h5.ints(c2 + "/state"), (std::vector<int>{2, 1}));
  EXPECT_EQ(h5.doubles(c2 + "/gap"), (std::vector<double>{-2e-4, 2e-5}));
  EXPECT_EQ(h5.doubles(c2 + "/normal_force"), (std::vector<double>{2e5, 0}));
  EXPECT_EQ(h5.doubles(c2 + "/shear_force"), (std::vector<double>{-3.5, 1.25}));
  EXPECT_EQ(h5.ints(c2 + "/block_i"), (std::vector<int>{1, 2}));
  EXPECT_EQ(h5.ints(c2 + "/block_j"), (std::vector<int>{0, 0}));
  EXPECT_EQ(h5.ints(c2 + "/cells"), (std::vector<int>{0, 1}));
  EXPECT_EQ(h5.ints(frame(3) + "/contacts/state"), (std::vector<int>{2, 1, 0}));
}

TEST(results_writer, XdmfIndexReferencesEveryFrameInTheHdf5File) {
  const fs::path dir = fresh_output_dir();
  write_frames(dir, 4);
  const std::string xml = read_text(dir / "results.xdmf");
  H5Reader h5(dir / "results.h5");

  EXPECT_TRUE(xml_tags_balanced(xml));
  EXPECT_NE(xml.find("<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">"),
            std::string::npos);
  EXPECT_EQ(count_occurrences(xml, "CollectionType=\"Temporal\""), 1);
  EXPECT_EQ(count_occurrences(xml, "CollectionType=\"Spatial\""), 4);
  EXPECT_EQ(xdmf_times(xml), (std::vector<double>{0, 0.25, 0.5, 0.75}));
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"blocks\""), 4);
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"contacts\""), 3);  // frames 1, 2, 3
  EXPECT_EQ(count_occurrences(xml, "TopologyType=\"Triangle\" NumberOfElements=\"14\""), 4);
  EXPECT_EQ(count_occurrences(xml, "TopologyType=\"Polyvertex\" NumberOfElements=\"3\""), 1);
  for (const char* name : {"displacement", "velocity", "sxx", "syy", "sxy", "block_id"})
    EXPECT_EQ(count_occurrences(xml, std::string("<Attribute Name=\"") + name + "\""), 4) << name;
  for (const char* name :
       {"normal", "state", "gap", "normal_force", "shear_force", "block_i", "block_j"})
    EXPECT_EQ(count_occurrences(xml, std::string("<Attribute Name=\"") + name + "\""), 3) << name;
  EXPECT_NE(xml.find("results.h5:/frames/000003/contacts/normal_force"), std::string::npos);
  expect_xdmf_refs_match(xml, h5);
}

// Every attribute carries its unit in an <Information> element (ParaView
// ignores it), and the Temporal collection says that the times are in s and
// what the scene's unit is (docs/output.md).
TEST(results_writer, XdmfIndexNotesTheUnitsOfTheFieldsAndOfTime) {
  const fs::path dir = fresh_output_dir();
  write_frames(dir, 2, TimeUnit{"d", 86400});
  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_TRUE(xml_tags_balanced(xml));
  EXPECT_EQ(count_occurrences(xml, "<Attribute "),
            count_occurrences(xml, "<Information Name=\"unit\""));
  const auto unit_of = [&xml](const std::string& name) {
    const std::string head = "<Attribute Name=\"" + name + "\"";
    const std::size_t at = xml.find(head);
    const std::size_t value = xml.find("<Information Name=\"unit\" Value=\"", at);
    if (at == std::string::npos || value == std::string::npos) return std::string("none");
    const std::size_t from = value + std::string("<Information Name=\"unit\" Value=\"").size();
    return xml.substr(from, xml.find('"', from) - from);
  };
  EXPECT_EQ(unit_of("displacement"), "m");
  EXPECT_EQ(unit_of("velocity"), "m/s");
  EXPECT_EQ(unit_of("sxx"), "Pa");
  EXPECT_EQ(unit_of("block_id"), "-");
  EXPECT_EQ(unit_of("gap"), "m");
  EXPECT_EQ(unit_of("normal_force"), "N/m");
  EXPECT_EQ(unit_of("state"), "-");
  const std::size_t temporal = xml.find("CollectionType=\"Temporal\">\n");
  ASSERT_NE(temporal, std::string::npos);
  EXPECT_EQ(xml.find("      <Information Name=\"time_unit\" Value=\"s\"/>\n"
                     "      <Information Name=\"scene_time_unit\" Value=\"d\"/>\n"
                     "      <Information Name=\"scene_time_unit_seconds\" Value=\"86400\"/>\n"
                     "      <Grid Name=\"frame_000000\""),
            temporal + std::string("CollectionType=\"Temporal\">\n").size());
}

TEST(results_writer, IndexIsRewrittenAfterEveryFrameWithoutLeftovers) {
  const fs::path dir = fresh_output_dir();
  OutputParts parts;
  ResultsWriter writer(dir, parts.results());
  // Before any frame: a valid, empty time series.
  std::string xml = read_text(dir / "results.xdmf");
  EXPECT_TRUE(xml_tags_balanced(xml));
  EXPECT_TRUE(xdmf_times(xml).empty());

  RockMass s = output_test_state();
  for (int k = 0; k < 3; ++k) {
    set_output_test_frame(s, k);
    writer.write_frame(s, s.time);
    xml = read_text(dir / "results.xdmf");
    EXPECT_TRUE(xml_tags_balanced(xml));
    EXPECT_EQ(xdmf_times(xml).size(), static_cast<std::size_t>(k + 1));
  }
  EXPECT_FALSE(fs::exists(dir / "results.xdmf.tmp"));
}

TEST(results_writer, RejectsAChangedTopologyAndKeepsGoing) {
  const fs::path dir = fresh_output_dir();
  OutputParts parts;
  ResultsWriter writer(dir, parts.results());
  RockMass s = output_test_state();
  writer.write_frame(s, 0);

  RockMass cut = s;
  cut.blocks[1].polygon = Polygon({{0, 1}, {2, 1}, {0, 3}});
  cut.blocks[1].initial_vertices = cut.blocks[1].polygon.vertices;
  try {
    writer.write_frame(cut, 1);
    FAIL() << "a block with fewer vertices was accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("block 1 ('ell')"), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.n_frames(), 1);
  EXPECT_THROW(writer.write_frame(s, 0), IoError);  // time must increase
  EXPECT_THROW(writer.write_frame(s, std::nan("")), IoError);

  set_output_test_frame(s, 2);
  writer.write_frame(s, s.time);
  EXPECT_EQ(writer.n_frames(), 2);
  EXPECT_EQ(xdmf_times(read_text(dir / "results.xdmf")), (std::vector<double>{0, 0.5}));
}

TEST(results_writer, UnwritableFolderIsAnIoErrorNamingTheFile) {
  const fs::path dir = fs::path(FISSURE_BINARY_DIR) / "test-output" / "no" / "such" / "folder";
  fs::remove_all(dir);
  try {
    OutputParts parts;
    ResultsWriter writer(dir, parts.results());
    FAIL() << "no error for a missing folder";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((dir / "results.h5").string()), std::string::npos) << what;
    EXPECT_NE(what.find("cannot create the file"), std::string::npos) << what;
  }
}

TEST(results_writer, InconsistentBlockIsAnIoErrorNamingTheBlock) {
  const fs::path dir = fresh_output_dir();
  OutputParts parts;
  ResultsWriter writer(dir, parts.results());
  RockMass s = output_test_state();
  s.blocks[2].initial_vertices.pop_back();
  try {
    writer.write_frame(s, 0);
    FAIL() << "inconsistent block accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("block 2 ('ring')"), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.n_frames(), 0);
}
