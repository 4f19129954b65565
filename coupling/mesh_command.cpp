#include "coupling/mesh_command.h"

#include <cstdio>
#include <filesystem>

#include "coupling/output_folder.h"
#include "coupling/plot_script.h"
#include "coupling/process_registry.h"
#include "rockmass/rock_mass_output.h"

namespace fissure {

int mesh_command(const std::string& scene_file, std::string outdir, bool plot) {
  // 1. Read the scene; its rock mass is generated while it is read.
  const Scene scene = read_scene(scene_file);
  const bool chosen = !outdir.empty();
  if (!chosen) outdir = default_output_folder(scene_file).string();
  if (const auto warning = check_output_folder(outdir, kRunRecord, scene_file, scene.name, chosen))
    std::fprintf(stderr, "warning: %s\n", warning->c_str());

  // 2. Blocks and fracture graph as frame 0, summary.json with the counts.
  write_rock_mass(scene, outdir);
  const nlohmann::json s = rock_mass_summary(scene);
  std::printf("%s: %zu blocks (%d fixed), %d fracture segments (%d nodes) from %ld fractures\n",
              scene.name.c_str(), scene.blocks.size(), s["fixed_blocks"].get<int>(),
              s["segments"].get<int>(), s["nodes"].get<int>(), s["fractures_in_rock"].get<long>());
  std::printf("  network: %d components (%d isolated, %d dead-end), %d dead-end segments\n",
              s["components"].get<int>(), s["isolated_components"].get<int>(),
              s["dead_end_components"].get<int>(), s["dead_end_segments"].get<int>());
  for (const auto& [pair, yes] : s["percolation"].items())
    if (yes.get<bool>()) std::printf("  percolates: %s\n", pair.c_str());
  std::printf("  generation %.3f s, cutting %.3f s\n", s["generation_seconds"].get<double>(),
              s["cutting_seconds"].get<double>());
  std::printf("  results: %s/ (results.xdmf for ParaView, summary.json)\n", outdir.c_str());

  // 3. The picture (python3 with h5py and matplotlib, when available).
  if (plot) {
    if (run_plot_script("plot_rock_mass.py", outdir))
      std::printf("  picture: %s/rock_mass.png\n", outdir.c_str());
    else
      std::printf(
          "  picture: not made (needs python3 with h5py and matplotlib: "
          "scripts/plot_rock_mass.py)\n");
  }
  return 0;
}

}  // namespace fissure
