#include "mechanics/dda/create_dda_process.h"

#include <unistd.h>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "mechanics/dda/dda_process.h"

namespace fissure::dda {

namespace {

// Peak memory of the DDA per block and per vertex: 405-433 MB at 10,010
// bricks with `auto` (docs/performance.md, dda_scaling), about 43 KB per
// four-vertex block, taken as 40 KB per block and 1 KB per vertex.
constexpr double kBytesPerBlock = 40e3, kBytesPerVertex = 1e3;

/// Refuses, before anything is allocated, a scene whose DDA would need more
/// memory than the machine has (issue 22, item 3).
void check_memory(const Scene& scene) {
  double vertices = 0;
  for (const BlockSpec& b : scene.blocks) vertices += b.polygon.n_vertices();
  const double blocks = static_cast<double>(scene.blocks.size());
  const double needed = blocks * kBytesPerBlock + vertices * kBytesPerVertex;
  const double machine =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (machine > 0 && needed > machine)
    throw SceneError(fmt::format(
        "{}: found {:.0f} blocks with {:.0f} vertices; the DDA would need about {:.3g} GB "
        "(40 KB per block and 1 KB per vertex, docs/performance.md), more than this machine's "
        "{:.3g} GB; expected a smaller scene",
        scene.source.string(), blocks, vertices, needed / 1e9, machine / 1e9));
}

}  // namespace

std::unique_ptr<Process> create_dda_process(const Scene& scene) {
  check_memory(scene);
  return std::make_unique<DdaProcess>(scene);
}

}  // namespace fissure::dda
