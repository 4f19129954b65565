#include "continuum/poroelasticity/create_continuum_process.h"

#include "continuum/poroelasticity/continuum_process.h"

namespace fissure::continuum {

std::unique_ptr<Process> create_continuum_process(const Scene& scene) {
  return std::make_unique<ContinuumProcess>(scene);
}

}  // namespace fissure::continuum
