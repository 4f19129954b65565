// Factory for Shi's DDA process (registered as physics "mechanics", method "dda").
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"

namespace fissure {

std::unique_ptr<Process> create_dda_process(const Scene& scene);

}  // namespace fissure
