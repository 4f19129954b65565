// Factory of the cubic-law flow process: the registry's row "flow"
// (coupling/process_registry.cpp). Its section is read by
// read_flow_settings.cpp into the scene before anything runs.
#pragma once

#include <memory>

#include "core/process/process.h"
#include "core/scene/scene.h"
#include "flow/cubic_law/flow_controls.h"  // flow::kFlowSection

namespace fissure::flow {

std::unique_ptr<Process> create_cubic_law_process(const Scene& scene);

}  // namespace fissure::flow
