// Top-level keys `name`, `physics` and `gravity`.
#include <algorithm>

#include "core/scene/scene_draft.h"

namespace fissure {

namespace {

/// Two processes that write the same shared field (the DDA and the DEM both
/// move the blocks) cannot both be switched on: reported at the second.
bool writes_what_another_writes(const ConfigNode& item, const std::string& physics,
                                const Scene& scene, std::span<const SceneSection> sections) {
  const SectionReader* reader = nullptr;
  for (const SceneSection& s : sections)
    if (s.physics == physics) reader = s.reader;
  for (const SceneSection& s : sections) {
    if (s.physics.empty() || !scene.has_physics(std::string(s.physics))) continue;
    for (std::string_view field : s.reader->provides)
      for (std::string_view mine : reader->provides)
        if (field == mine) {
          item.error("found '" + physics + "' beside '" + std::string(s.physics) +
                     "', which writes the same field '" + std::string(field) +
                     "'; expected one process that moves the blocks");
          return true;
        }
  }
  return false;
}

}  // namespace

void read_general(ConfigMap& top, SceneDraft& draft, std::span<const SceneSection> sections) {
  Scene& scene = draft.scene;

  // name: the scene's name in summary.json, the pictures and the
  // checkpoint; the default output folder is named after the file, not this.
  if (auto node = top.optional("name"))
    if (auto name = node->string("a scene name")) scene.name = *name;

  // physics: the processes the scene switches on (the registry's names).
  std::vector<std::string_view> known;
  for (const SceneSection& s : sections)
    if (!s.physics.empty()) known.push_back(s.physics);
  std::string known_list;
  for (std::string_view p : known) known_list += (known_list.empty() ? "" : ", ") + std::string(p);
  if (auto node =
          top.required("physics", "a non-empty list of physics names (" + known_list + ")")) {
    if (auto items = node->list("physics names (" + known_list + ")", true)) {
      for (const ConfigNode& item : *items) {
        const std::optional<std::string> p = item.choice(known);
        if (p && scene.has_physics(*p))
          item.error("found '" + *p + "' a second time; expected each physics name once");
        else if (p && !writes_what_another_writes(item, *p, scene, sections))
          scene.physics.push_back(*p);
      }
      // The list was read: what it does not switch on is off, even when some
      // of its names were unknown.
      draft.physics_read = true;
      // Where the processes' order is written until coupling.order says.
      scene.coupling.order_location = node->location();
    }
  }

  if (auto node = top.optional("gravity"))
    if (auto g = node->vec2(quantity::acceleration)) scene.gravity = *g;
}

}  // namespace fissure
