#include "rockmass/rock_mass_output.h"

#include "core/base/stopwatch.h"

#include <algorithm>

#include "core/geometry/network_connectivity.h"
#include "core/io/results_writer.h"
#include "core/io/summary_writer.h"
#include "core/state/rock_mass.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/fracture_graph_results.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

nlohmann::json rock_mass_summary(const Scene& scene) {
  static const FractureGraph kNoGraph;
  static const RockMassStatistics kNoStatistics;
  const FractureGraph* graph = scene.initial_fields.find(kFractureGraph);
  const RockMassStatistics* statistics = scene.sections.find(kRockMassStatistics);
  const FractureGraph& g = graph ? *graph : kNoGraph;
  const RockMassStatistics& s = statistics ? *statistics : kNoStatistics;
  std::vector<std::pair<int, int>> ends;
  ends.reserve(g.segments.size());
  for (const FractureSegment& f : g.segments) ends.emplace_back(f.node_a, f.node_b);
  const NetworkConnectivity c = analyze_connectivity(g.n_nodes(), ends, g.boundary_nodes);

  nlohmann::ordered_json j;
  j["blocks"] = scene.blocks.size();
  j["fixed_blocks"] = std::count_if(scene.blocks.begin(), scene.blocks.end(),
                                    [](const BlockSpec& b) { return b.fixed; });
  j["estimated_blocks"] = s.estimated_blocks;
  j["fractures_generated"] = s.generated_fractures;
  j["fractures_in_rock"] = s.cut_fractures;
  j["nodes"] = g.n_nodes();
  j["segments"] = g.n_segments();
  double length = 0;
  for (int i = 0; i < g.n_segments(); ++i) length += g.length(i);
  j["total_length"] = length;
  j["components"] = c.n_components;
  j["isolated_components"] = c.n_isolated();
  j["dead_end_components"] = c.n_dead_end_components();
  j["dead_end_segments"] = c.n_dead_end_segments();
  nlohmann::ordered_json percolation = nlohmann::ordered_json::object();
  std::vector<std::string> names;
  for (const auto& [name, nodes] : g.boundary_nodes) names.push_back(name);
  for (size_t a = 0; a < names.size(); ++a)
    for (size_t b = a + 1; b < names.size(); ++b)
      percolation[names[a] + "-" + names[b]] = c.percolates(names[a], names[b]);
  j["percolation"] = percolation;
  j["slivers_merged"] = s.slivers_merged;
  j["vertices_merged"] = s.vertices_merged;
  j["invalid_merged"] = s.invalid_merged;
  j["generation_seconds"] = s.generation_seconds;
  j["cutting_seconds"] = s.cutting_seconds;
  return j;
}

void write_rock_mass(const Scene& scene, const std::filesystem::path& outdir) {
  const Stopwatch clock;
  std::filesystem::create_directories(outdir);
  const RockMass state = RockMass::from_scene(scene);
  {
    FractureGraphResults graph;
    ResultsWriter results(outdir, {&graph});
    results.write_frame(state, 0.0);
  }
  RunSummary summary;
  summary.scene = scene.name;
  summary.scene_file = recorded_file_path(scene.source);
  summary.status = "meshed";
  summary.output_frames = 1;
  summary.rock_mass = rock_mass_summary(scene);
  summary.wall_seconds = clock.seconds();
  write_summary(outdir / "summary.json", summary);
}

}  // namespace fissure
