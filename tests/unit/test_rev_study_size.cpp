// The REV study's size check (docs/flow.md section 8, "Size check"): the
// network nodes a study will build are estimated before anything is built,
// the estimate matches the networks built, and a study typed an order of
// magnitude too dense is refused with the study file's line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/base/errors.h"
#include "flow/rev/read_rev_study.h"
#include "flow/rev/rev_dfn_source.h"
#include "flow/rev/rev_study.h"

namespace fissure {
namespace {

std::string example_study() {
  std::ifstream in(std::filesystem::path(FISSURE_SOURCE_DIR) / "configs" / "flow_rev_study.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// "study.yaml:LINE:3: network", where the text's `network:` map starts
/// (its first key, on the line after `network:`).
std::string network_location(const std::string& text) {
  const std::size_t at = text.find("\nnetwork:");
  int line = 3;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return "study.yaml:" + std::to_string(line) + ":3: network";
}

TEST(rev_study_size, EstimateMatchesTheNetworksOfTheExampleDfn) {
  // The example's four families (P21 6.4 1/m, traces 1-10 m): the estimate
  // counts crossings (the Buffon intersection density) and two ends per
  // trace. Built networks also have nodes where traces meet the square's
  // sides, ~10 % more at 10-20 m; 4 realizations x 3 rotations of ~2,000 and
  // ~7,000 nodes leave a sampling spread of a few per cent.
  flow::RevStudy study =
      flow::read_rev_study_text(example_study(), "study.yaml", rev_dfn_source_factory());
  study.config.sizes = {10, 20};
  study.config.realizations = 4;
  study.config.threads = 2;
  const double estimate = flow::expected_study_nodes(study.config, *study.source);
  EXPECT_NEAR(estimate,
              4 * 3 * (study.source->expected_nodes(10) + study.source->expected_nodes(20)),
              1e-9 * estimate)
      << "12 rotations of 30 deg are 3 distinct squares modulo 90 deg";
  const flow::RevStudyResult r = flow::run_rev_study(study.config, *study.source);
  std::map<int, std::pair<double, int>> built;  // size index -> (nodes, domains)
  for (const flow::DomainResult& d : r.domains) {
    built[d.size_index].first += d.n_nodes;
    built[d.size_index].second += 1;
  }
  for (int s = 0; s < 2; ++s) {
    const double mean = built[s].first / built[s].second;
    const double expected = study.source->expected_nodes(study.config.sizes[s]);
    EXPECT_NEAR(mean / expected, 1.0, 0.15)
        << "size " << study.config.sizes[s] << " m: built " << mean << ", estimated " << expected;
  }
}

TEST(rev_study_size, ParallelSetsEstimateBoundsTheNetwork) {
  // Two orthogonal sets 0.5 m apart in a 10 m square: 20 x 20 crossings
  // (21 x 21 with the traces on the sides) and at most sqrt(2) 10 / 0.5
  // traces per set with two ends each; the rotated square has the most.
  const flow::RevStudy study = flow::read_rev_study_text(
      "network: {type: regular, sets: [{angle: 0, spacing: 0.5, aperture: 100 um},\n"
      "  {angle: 90 deg, spacing: 0.5, aperture: 100 um}]}\nsizes: [10]\n",
      "study.yaml");
  const double estimate = study.source->expected_nodes(10);
  EXPECT_NEAR(estimate, 400 + 4 * std::sqrt(2.0) * 20, 1e-9);
  for (double angle : {0.0, 0.3, 0.785}) {
    const double nodes = static_cast<double>(study.source->domain(0, 10, angle).nodes.size());
    EXPECT_LE(nodes, 1.05 * estimate) << "rotation " << angle;
    EXPECT_GE(nodes, 0.75 * estimate) << "rotation " << angle;
  }
}

TEST(rev_study_size, ADensityTypedWrongIsRefusedBeforeAnythingIsBuilt) {
  // The fuzzer's case 9331: family c's P21 typed 140 1/m for 1.4 gives about
  // 2.2e7 nodes for one realization (150 s on one core), 4.4e8 for the
  // study's 20 (50 minutes); refused at once, at the study's `network` line.
  const std::string text =
      replaced(example_study(), "density: {p21: 1.4 1/m}", "density: {p21: 140 1/m}");
  flow::RevStudy study = flow::read_rev_study_text(text, "study.yaml", rev_dfn_source_factory());
  study.config.realizations = 1;  // as `--realizations 1`: applied before the check
  std::string message;
  try {
    flow::run_rev_study(study.config, *study.source);
  } catch (const SceneError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(network_location(text) +
                         ": found a network expected to give about 2.19e+07 nodes"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("20 sizes x 1 realizations x 12 rotations, more than max_nodes = 1e+07"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("or a larger max_nodes"), std::string::npos) << message;

  // A user who means it raises the limit.
  flow::RevStudy allowed =
      flow::read_rev_study_text(text + "max_nodes: 3e7\n", "study.yaml", rev_dfn_source_factory());
  allowed.config.realizations = 1;
  EXPECT_NO_THROW(flow::check_study_size(allowed.config, *allowed.source));
  // ... but not by twenty realizations.
  allowed.config.realizations = 20;
  EXPECT_THROW(flow::check_study_size(allowed.config, *allowed.source), SceneError);
}

TEST(rev_study_size, ASpacingTypedWrongIsRefused) {
  // 1 mm for 1 m: 1e8 crossings in each of the 3 distinct rotations of a
  // 10 m square.
  const flow::RevStudy study = flow::read_rev_study_text(
      "sizes: [10]\n"
      "network: {type: regular, sets: [{angle: 0, spacing: 1 mm, aperture: 100 um},\n"
      "  {angle: 90 deg, spacing: 1 mm, aperture: 100 um}]}\n",
      "study.yaml");
  try {
    flow::check_study_size(study.config, *study.source);
    ADD_FAILURE() << "not refused";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("study.yaml:2:10: network: found a network expected "
                                         "to give about 3e+08 nodes"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fissure
