#include "mechanics/dda/create_dda_process.h"

#include "mechanics/dda/dda_process.h"

namespace fissure {

std::unique_ptr<Process> create_dda_process(const Scene& scene) {
  return std::make_unique<dda::DdaProcess>(scene);
}

}  // namespace fissure
