#include "thermal/conduction/create_thermal_process.h"

#include "thermal/conduction/thermal_process.h"

namespace fissure::thermal {

std::unique_ptr<Process> create_thermal_process(const Scene& scene) {
  return std::make_unique<ThermalProcess>(scene);
}

}  // namespace fissure::thermal
