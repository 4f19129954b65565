// Reading and validating scene files (architecture.md 5). Every problem found
// is reported, not just the first: each as "file:line:column: key: what was
// found; expected ...". Nothing runs on an invalid scene.
#pragma once

#include <filesystem>
#include <string>

#include "core/scene/scene.h"

namespace fissure {

/// Parses and validates a scene file. Throws SceneError whose message lists
/// every problem, one per line.
Scene parse_scene(const std::filesystem::path& file);

/// Same, from text; `file_name` is used in messages and for the scene name.
Scene parse_scene_text(const std::string& yaml, const std::string& file_name);

}  // namespace fissure
