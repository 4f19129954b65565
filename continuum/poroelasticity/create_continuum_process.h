// Factory of the continuum process: the registry's row "continuum"
// (coupling/process_registry.cpp). Its section is read by
// read_continuum_settings.cpp into the scene before anything runs.
#pragma once

#include <memory>

#include "continuum/poroelasticity/continuum_settings.h"  // continuum::kContinuumSection
#include "core/process/process.h"
#include "core/scene/scene.h"

namespace fissure::continuum {

std::unique_ptr<Process> create_continuum_process(const Scene& scene);

}  // namespace fissure::continuum
