// A file named in a scene, relative to the scene file's folder unless
// absolute: ground-motion records, REV and stress studies.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "core/scene/config_node.h"

namespace fissure {

/// The existing file that `node` names (a string), resolved against the
/// folder of `scene_file`; nullopt, reported at `node` ("found no file ...;
/// expected `what`"), when it names none.
std::optional<std::filesystem::path> scene_relative_file(const ConfigNode& node,
                                                         const std::filesystem::path& scene_file,
                                                         std::string_view what);

}  // namespace fissure
