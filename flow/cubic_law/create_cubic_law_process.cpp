#include "flow/cubic_law/create_cubic_law_process.h"

#include "flow/cubic_law/cubic_law_process.h"

namespace fissure::flow {

std::unique_ptr<Process> create_cubic_law_process(const Scene& scene) {
  return std::make_unique<CubicLawProcess>(scene);
}

}  // namespace fissure::flow
