// The REV study under stress at the size of issue 38 (docs/performance.md,
// "REV under stress"): the rock mass of configs/rev_stress_rock.yaml, 8
// sizes (1.25 to 10 m) x 10 realizations x 5 stress states x 1 rotation,
// on 1 and on 2 threads. Prints the wall times, their ratio, and the cost
// of a square against its blocks; writes results.csv (every square) for
// plot.py.
#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <array>
#include <map>
#include <memory>

#include "core/base/stopwatch.h"
#include "coupling/process_registry.h"
#include "coupling/upscaling/scene_rock_mass_source.h"
#include "coupling/upscaling/stress_study.h"

using namespace fissure;

namespace {

StressState principal(double sigma_1, double sigma_3) {
  StressState s;
  s.stress << -sigma_1, -sigma_3, 0;
  return s;
}

}  // namespace

int main() {
  const auto scene = std::make_shared<const Scene>(
      read_scene(std::filesystem::path(FISSURE_SOURCE_DIR) / "configs" / "rev_stress_rock.yaml"));
  flow::RevStudyConfig study;
  for (int k = 1; k <= 8; ++k) study.sizes.push_back(1.25 * k);
  study.realizations = 10;
  study.rotations = 1;
  StressStudyConfig config;
  // Min et al.'s two series: magnitude at a ratio of 1.3, and the ratio at 5 MPa.
  config.states = {principal(1.3e6, 1e6), principal(6.5e6, 5e6), principal(13e6, 10e6),
                   principal(10e6, 5e6), principal(15e6, 5e6)};
  const SceneRockMassSource source(scene, Vec2::Zero());

  std::printf("%zu sizes x %d realizations x %zu states: %zu squares\n", study.sizes.size(),
              study.realizations, config.states.size(),
              study.sizes.size() * study.realizations * config.states.size());
  std::vector<StressStateResult> results;
  double seconds[2] = {0, 0};
  for (int threads : {1, 2}) {
    study.threads = threads;
    const Stopwatch clock;
    results = run_stress_study(study, config, source, {});
    seconds[threads - 1] = clock.seconds();
    std::printf("  %d thread(s): %.1f s wall\n", threads, seconds[threads - 1]);
  }
  std::printf("  speed-up on 2 threads: %.2f\n", seconds[0] / seconds[1]);

  // Cost against blocks, from the last (2-thread) run's per-square times.
  std::ofstream csv(std::filesystem::path(FISSURE_SOURCE_DIR) / "benchmarks" / "rev_stress" /
                    "results.csv");
  csv << "state,size,realization,blocks,contacts,cycles,at_rest,seconds\n";
  // Per size: blocks, cycles, seconds, squares, block-cycles.
  std::map<double, std::array<double, 5>> by_size;
  for (std::size_t s = 0; s < results.size(); ++s)
    for (const flow::DomainResult& d : results[s].rev.domains) {
      const double size = study.sizes[d.size_index];
      csv << fmt::format("{},{},{},{},{},{},{},{:.5g}\n", s, size, d.realization,
                         d.mechanics.blocks, d.mechanics.contacts, d.mechanics.cycles,
                         d.mechanics.equilibrium ? 1 : 0, d.seconds);
      auto& row = by_size[size];
      row[0] += d.mechanics.blocks, row[1] += static_cast<double>(d.mechanics.cycles);
      row[2] += d.seconds, row[3] += 1;
      row[4] += d.mechanics.blocks * static_cast<double>(d.mechanics.cycles);
    }
  std::printf("%8s %8s %8s %12s %14s\n", "size (m)", "blocks", "cycles", "s / square",
              "us / block-cycle");
  for (const auto& [size, row] : by_size)
    std::printf("%8.2f %8.0f %8.0f %12.4f %14.3f\n", size, row[0] / row[3], row[1] / row[3],
                row[2] / row[3], 1e6 * row[2] / std::max(1.0, row[4]));
  return 0;
}
