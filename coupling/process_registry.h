// One table from the scene's physics names to process factories (style.md 2:
// adding a process means one folder plus one row here).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/process/process.h"
#include "core/scene/scene.h"

namespace fissure {

/// Builds only the processes the scene activates, in coupling order.
std::vector<std::unique_ptr<Process>> create_processes(const Scene& scene);

/// Physics names the registry knows (for scene validation messages).
std::vector<std::string> known_physics();

}  // namespace fissure
