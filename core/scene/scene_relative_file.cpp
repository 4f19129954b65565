#include "core/scene/scene_relative_file.h"

#include <fmt/format.h>

namespace fissure {

std::optional<std::filesystem::path> scene_relative_file(const ConfigNode& node,
                                                         const std::filesystem::path& scene_file,
                                                         std::string_view what) {
  const std::optional<std::string> name = node.string("a file");
  if (!name) return std::nullopt;
  std::filesystem::path path(*name);
  const bool relative = path.is_relative();
  if (relative) path = scene_file.parent_path() / path;
  if (std::filesystem::is_regular_file(path)) return path;
  // Said plainly: the usual cause is a scene copied away from its files.
  node.error(fmt::format("found no file {}{}; expected {}", path.string(),
                         relative ? " (the path is relative to the scene file's folder)" : "",
                         what));
  return std::nullopt;
}

}  // namespace fissure
