// The fracture network's flow state in results.h5 + results.xdmf
// (core/io/fracture_output, results_writer; docs/output.md): per frame the
// node pressures (and heads), the segment apertures and fluxes, read back
// exactly; a "fractures" grid next to the blocks in every frame whose
// references name datasets of the right shape; a graph that changes gets its
// own geometry in the frame.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/io/results_writer.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fracture_graph.h"
#include "tests/support/output_parts.h"
#include "tests/support/output_test_state.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fs = std::filesystem;
using namespace fissure;
using namespace fissure::test;

namespace {

/// This test's own scratch folder.
fs::path fresh_output_dir() {
  return fissure::testing::scratch_dir("fracture_results");
}

/// The joints of the output test state: along the top of the base (0, 1) -
/// (2, 1) - (4, 1) and up between the L and the ring, (2, 1) - (2, 3).
FractureGraph test_graph() {
  FractureGraph g;
  g.nodes = {{0, 1}, {2, 1}, {4, 1}, {2, 3}};
  for (auto [a, b] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{1, 3}}) {
    FractureSegment s;
    s.node_a = a;
    s.node_b = b;
    s.aperture = 1e-4;
    g.segments.push_back(s);
  }
  g.boundary_nodes["left"] = {0};
  return g;
}

/// Frame k's flow state (exact binary fractions: compared with ==).
FractureFlowState test_flow(int k) {
  FractureFlowState f;
  f.pressure = {4e5 + k, 2.5e5, 1e5, 3e5 - k};
  f.aperture_a = {1.25e-4, 0.5e-4, 1e-4};
  f.aperture_b = {0.75e-4, 0.5e-4, 1e-4 + k * 0.25e-4};
  f.flux = {0.5 * (k + 1), 0.25, -0.125};
  return f;
}

RockMass state_with_flow(int k) {
  RockMass s = output_test_state();
  set_output_test_frame(s, k);
  s.fields.set(kFractureGraph, test_graph());
  s.fields.set(kFractureFlow, test_flow(k));
  return s;
}

std::string frame(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%06d", k);
  return name;
}

}  // namespace

TEST(fracture_results, EveryFrameHoldsTheFlowStateOnTheMeshGraph) {
  const fs::path dir = fresh_output_dir();
  {
    OutputParts parts;
    ResultsWriter writer(dir, parts.results());
    for (int k = 0; k < 3; ++k) writer.write_frame(state_with_flow(k), frame_time(k));
  }
  H5Reader h5(dir / "results.h5");
  EXPECT_EQ(h5.doubles("/mesh/fractures/nodes"), (std::vector<double>{0, 1, 2, 1, 4, 1, 2, 3}));
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    const std::string f = frame(k) + "/fractures/";
    const FractureFlowState expected = test_flow(k);
    EXPECT_EQ(h5.doubles(f + "pressure"), expected.pressure);
    EXPECT_EQ(h5.shape(f + "pressure"), (std::vector<hsize_t>{4}));
    EXPECT_EQ(h5.doubles(f + "aperture_a"), expected.aperture_a);
    EXPECT_EQ(h5.doubles(f + "aperture_b"), expected.aperture_b);
    EXPECT_EQ(h5.doubles(f + "flux"), expected.flux);
    const std::vector<double> mean = h5.doubles(f + "aperture_mean");
    ASSERT_EQ(mean.size(), 3u);
    for (int s = 0; s < 3; ++s)
      EXPECT_EQ(mean[s], 0.5 * (expected.aperture_a[s] + expected.aperture_b[s]));
    // The graph is the one in /mesh: no copy of it, and no heads without gravity.
    EXPECT_FALSE(h5.exists(f + "nodes"));
    EXPECT_FALSE(h5.exists(f + "segments"));
    EXPECT_FALSE(h5.exists(f + "head"));
  }

  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_TRUE(xml_tags_balanced(xml));
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"blocks\""), 3);
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"fractures\""), 3);
  EXPECT_EQ(count_occurrences(xml, "TopologyType=\"Polyline\" NumberOfElements=\"3\""), 3);
  EXPECT_EQ(count_occurrences(xml, "results.h5:/mesh/fractures/nodes<"), 3);
  EXPECT_EQ(count_occurrences(xml,
                              "<Attribute Name=\"pressure\" AttributeType=\"Scalar\" "
                              "Center=\"Node\""),
            3);
  for (const char* name : {"aperture_a", "aperture_b", "aperture_mean", "flux", "component"})
    EXPECT_EQ(count_occurrences(xml, std::string("<Attribute Name=\"") + name +
                                         "\" AttributeType=\"Scalar\" Center=\"Cell\""),
              3)
        << name;
  EXPECT_NE(xml.find("results.h5:/frames/000002/fractures/flux"), std::string::npos);
  EXPECT_EQ(xml.find("Name=\"head\""), std::string::npos);
  expect_xdmf_refs_match(xml, h5);
}

TEST(fracture_results, HeadsWhenTheFlowHasGravity) {
  const fs::path dir = fresh_output_dir();
  {
    // rho_f |g| = 1e4 Pa/m: h = p / 1e4 + y.
    OutputParts parts(HeadDefinition{1000, Vec2(0, -10)});
    ResultsWriter writer(dir, parts.results());
    writer.write_frame(state_with_flow(0), 0);
  }
  H5Reader h5(dir / "results.h5");
  EXPECT_EQ(h5.doubles(frame(0) + "/fractures/head"), (std::vector<double>{41, 26, 11, 33}));
  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_EQ(count_occurrences(xml,
                              "<Attribute Name=\"head\" AttributeType=\"Scalar\" "
                              "Center=\"Node\""),
            1);
  expect_xdmf_refs_match(xml, h5);
}

TEST(fracture_results, AChangedGraphIsWrittenWithTheFrame) {
  const fs::path dir = fresh_output_dir();
  {
    OutputParts parts;
    ResultsWriter writer(dir, parts.results());
    writer.write_frame(state_with_flow(0), 0);
    // A rebuilt network: the vertical joint now ends at (2, 2.5), and a new
    // segment continues the bottom joint.
    RockMass s = state_with_flow(1);
    FractureGraph& graph = s.fields.get(kFractureGraph);
    graph.nodes[3] = Vec2(2, 2.5);
    graph.nodes.push_back(Vec2(5, 1));
    graph.segments.push_back(graph.segments[1]);
    graph.segments[3].node_a = 2;
    graph.segments[3].node_b = 4;
    FractureFlowState& flow = s.fields.get(kFractureFlow);
    flow.pressure.push_back(0);
    flow.aperture_a.push_back(1e-5);
    flow.aperture_b.push_back(1e-5);
    flow.flux.push_back(0.25);
    writer.write_frame(s, 1);
    writer.write_frame(state_with_flow(2), 2);  // back to the first graph
  }
  H5Reader h5(dir / "results.h5");
  const std::string f1 = frame(1) + "/fractures/";
  EXPECT_EQ(h5.doubles(f1 + "nodes"), (std::vector<double>{0, 1, 2, 1, 4, 1, 2, 2.5, 5, 1}));
  EXPECT_EQ(h5.ints(f1 + "segments"), (std::vector<int>{0, 1, 1, 2, 1, 3, 2, 4}));
  EXPECT_EQ(h5.shape(f1 + "flux"), (std::vector<hsize_t>{4}));
  EXPECT_FALSE(h5.exists(frame(2) + "/fractures/nodes"));

  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"fractures\""), 3);
  EXPECT_EQ(count_occurrences(xml, "results.h5:/frames/000001/fractures/nodes<"), 1);
  EXPECT_EQ(count_occurrences(xml, "results.h5:/mesh/fractures/nodes<"), 2);
  // The fixed per-segment fields of /mesh belong to the other graph.
  EXPECT_EQ(count_occurrences(xml, "<Attribute Name=\"component\""), 2);
  expect_xdmf_refs_match(xml, h5);
}

TEST(fracture_results, AGraphWithoutFlowIsDrawnFromTheMesh) {
  // `fissure mesh` and runs without flow: the fixed graph only.
  const fs::path dir = fresh_output_dir();
  {
    OutputParts parts;
    ResultsWriter writer(dir, parts.results());
    RockMass s = output_test_state();
    s.fields.set(kFractureGraph, test_graph());
    writer.write_frame(s, 0);
    s.fields.get_or_add(kFractureFlow).pressure = {1, 2};  // of another graph: not drawn on it
    writer.write_frame(s, 1);
  }
  H5Reader h5(dir / "results.h5");
  EXPECT_FALSE(h5.exists(frame(0) + "/fractures"));
  EXPECT_FALSE(h5.exists(frame(1) + "/fractures"));
  const std::string xml = read_text(dir / "results.xdmf");
  EXPECT_EQ(count_occurrences(xml, "<Grid Name=\"fractures\""), 2);
  EXPECT_EQ(xml.find("Name=\"pressure\""), std::string::npos);
  expect_xdmf_refs_match(xml, h5);
}
