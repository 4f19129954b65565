#include "mechanics/dda/create_dda_process.h"

#include "mechanics/dda/dda_process.h"

namespace fissure::dda {

std::unique_ptr<Process> create_dda_process(const Scene& scene) {
  return std::make_unique<DdaProcess>(scene);
}

}  // namespace fissure::dda
