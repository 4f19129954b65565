// The modules' own sections (scene_section.h): each is read by its module's
// reader, and checked here against `physics` in the same words for every
// module. What a reader sees of the scene is a SectionContext.
#include <algorithm>

#include "core/scene/scene_draft.h"

namespace fissure {

namespace {

std::vector<SceneSection>& installed_sections() {
  static std::vector<SceneSection> sections;
  return sections;
}

}  // namespace

void install_scene_sections(std::span<const SceneSection> sections) {
  installed_sections().assign(sections.begin(), sections.end());
}

namespace {

/// Calls visit(reader) for the section of every process `scene` switches on.
template <class Visit>
void for_each_active_section(const Scene& scene, Visit&& visit) {
  for (const SceneSection& s : installed_sections())
    if (!s.physics.empty() && scene.has_physics(std::string(s.physics))) visit(*s.reader);
}

/// Calls visit(field) for every exchanged field of the processes `scene`
/// switches on.
template <class Visit>
void for_each_exchanged_field(const Scene& scene, Visit&& visit) {
  for_each_active_section(scene, [&](const SectionReader& r) {
    for (const ExchangedFieldKind& f : r.exchanges) visit(f);
  });
}

}  // namespace

bool provides(const Scene& scene, std::string_view field) {
  bool found = false;
  for_each_active_section(scene, [&](const SectionReader& r) {
    found = found || std::ranges::find(r.provides, field) != r.provides.end();
  });
  return found;
}

const ExchangedFieldKind* exchanged_field(const Scene& scene, std::string_view name) {
  const ExchangedFieldKind* found = nullptr;
  for_each_exchanged_field(scene, [&](const ExchangedFieldKind& f) {
    if (f.name == name) found = &f;
  });
  return found;
}

std::string exchanged_field_names(const Scene& scene) {
  std::string names;
  for_each_exchanged_field(scene, [&](const ExchangedFieldKind& f) {
    names += (names.empty() ? "" : ", ") + std::string(f.name);
  });
  return names;
}

Scene& SectionContext::scene() {
  return draft_.scene;
}

const NameRegistry& SectionContext::materials() const {
  return draft_.materials;
}

const NameRegistry& SectionContext::joints() const {
  return draft_.joints;
}

bool SectionContext::physics_read() const {
  return draft_.physics_read;
}

ConfigMap& SectionContext::top() {
  return *draft_.top;
}

void SectionContext::deprecated(const ConfigNode& node, std::string_view instead) {
  node.diagnostics().warning(node.key_location(), node.path(),
                             "is deprecated: write " + std::string(instead));
}

std::optional<int> SectionContext::material_entry(ConfigMap& entry, std::vector<bool>& given) {
  std::optional<int> index;
  if (auto n = entry.required("name", "the name of a material of `materials`")) {
    index = materials().resolve(*n);
    if (index && given[*index]) {
      n->error("found a material given twice; expected each material once");
      return std::nullopt;
    }
    if (index) given[*index] = true;
  }
  return index;
}

void read_module_section(ConfigMap& top, SceneDraft& draft, const SceneSection& section) {
  const SectionReader& reader = *section.reader;
  const std::string key(reader.key);
  const std::string physics(section.physics);
  const bool needed = !physics.empty() && draft.scene.has_physics(physics);
  std::optional<ConfigNode> node = top.optional(reader.key);
  if (!node) {
    if (needed) top.report_missing(reader.key, reader.expected);
    return;
  }
  if (!physics.empty() && !needed && draft.physics_read)
    node->error_at_key("found a " + key + " section, but physics does not list " + physics +
                       "; expected '" + physics + "' in physics, or no " + key + " section");

  const std::size_t problems = node->diagnostics().size();
  SectionContext context(draft);
  reader.read(*node, context);
  if (reader.generate && node->diagnostics().size() == problems)
    draft.pending_block_sources.push_back({&reader, node->key_location()});
}

}  // namespace fissure
