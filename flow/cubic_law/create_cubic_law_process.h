// Factory of the flow process for the process registry (coupling/process_registry.cpp).
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"

namespace fissure::flow {

std::unique_ptr<Process> create_cubic_law_process(const Scene& scene);

}  // namespace fissure::flow
