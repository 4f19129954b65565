// Factory of the explicit DEM process: the registry's row "dem"
// (coupling/process_registry.cpp). Its section is read by
// read_dem_settings.cpp into the scene before anything runs.
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"
#include "mechanics/dem/dem_settings.h"  // kDemSection

namespace fissure::dem {

std::unique_ptr<Process> create_dem_process(const Scene& scene);

}  // namespace fissure::dem
