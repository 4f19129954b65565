// Factory of Shi's DDA process: the registry's row "mechanics"
// (coupling/process_registry.cpp). Its section is read by
// read_dda_settings.cpp into the scene before anything runs.
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"
#include "mechanics/dda/dda_settings.h"  // dda::kMechanicsSection

namespace fissure::dda {

std::unique_ptr<Process> create_dda_process(const Scene& scene);

}  // namespace fissure::dda
