// Factory of the thermal process: the registry's row "thermal"
// (coupling/process_registry.cpp). Its section is read by
// read_thermal_settings.cpp into the scene before anything runs.
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"
#include "thermal/conduction/thermal_settings.h"  // thermal::kThermalSection

namespace fissure::thermal {

std::unique_ptr<Process> create_thermal_process(const Scene& scene);

}  // namespace fissure::thermal
