// A module's own top-level section of a scene file (docs/architecture.md 3):
// each process reads and checks its own section, a
// block source (the `rock_mass`) reads its section and generates blocks.
// core/scene reads only the keys that every module shares; the modules'
// readers come from the registry (coupling/process_registry.h), so every
// section is read, with the same file:line:column diagnostics and
// unknown-key checks, before anything runs, and core names no physics.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/config_map.h"
#include "core/scene/exchanged_field.h"
#include "core/scene/name_registry.h"
#include "core/scene/scene.h"

namespace fissure {

struct SceneDraft;

/// Geometric tolerance: 1e-9 x the largest extent of the bounding box of all
/// blocks (docs/scene-reference.md, "Geometry checks"); sections with
/// geometry of their own scale it the same way.
inline constexpr double kRelativeGeometryTolerance = 1e-9;

/// What a section's reader sees of the scene being read, and where it puts
/// what it read.
class SectionContext {
 public:
  explicit SectionContext(SceneDraft& draft) : draft_(draft) {}

  /// The scene read so far: the shared keys (physics, gravity, materials,
  /// joints, the `blocks` list, coupling), and the sections read before
  /// this one. A reader stores its settings in scene().sections and may set
  /// initial fields (scene().initial_fields).
  Scene& scene();
  /// Name lookups of materials and joints ("did you mean").
  const NameRegistry& materials() const;
  const NameRegistry& joints() const;
  /// Whether `physics` was read as a list: what it does not list is off.
  bool physics_read() const;
  /// The document's map, to report a missing top-level key that this
  /// section needs (report_missing).
  ConfigMap& top();
  /// A key that still works but is deprecated: a warning at `node`, "is
  /// deprecated: write `instead`". The scene runs.
  void deprecated(const ConfigNode& node, std::string_view instead);
  /// The `name` of an entry of a module's per-material list (thermal.
  /// materials[], continuum.materials[]): the index of the scene material
  /// it names, marked in `given`; nothing (reported) when it is missing,
  /// unknown or given twice.
  std::optional<int> material_entry(ConfigMap& entry, std::vector<bool>& given);

 private:
  SceneDraft& draft_;
};

/// How a module reads its section.
struct SectionReader {
  /// The top-level key.
  std::string_view key;
  /// What is expected when the section is required but missing, e.g. "a
  /// NAME section, because physics lists NAME (...)".
  std::string_view expected;
  /// Reads and checks the section; problems go to the node's diagnostics.
  void (*read)(const ConfigNode& section, SectionContext& context) = nullptr;
  /// Block sources only: called after every section was read, when this one
  /// was read without a problem; returns the generated blocks (appended to
  /// Scene::blocks, the first at index `first_block`). Throws fissure::Error
  /// ("what went wrong; expected what"), reported at the section's key.
  std::vector<BlockSpec> (*generate)(SectionContext& context, int first_block) = nullptr;
  /// Its documented keys (docs/scene-reference.md; checked by a test).
  std::span<const KeyTable* const> keys;
  /// Keys of the shared maps that moved into this section (an old scene
  /// that has one gets "unknown key ... (moved to ...)").
  std::span<const MovedKey> moved_keys = {};
  /// The section brings geometry of its own (a meshed domain): a scene that
  /// has it needs no `blocks`.
  bool own_geometry = false;
  /// The shared fields its process writes in every scene that switches it
  /// on (Process::writes() whatever the settings): other modules ask for a
  /// field with provides(), never for this module's name.
  std::span<const std::string_view> provides = {};
  /// The fields its process exchanges in the iterated scheme
  /// (Process::exchanged_values gives them in this order), each with its
  /// kind of quantity: coupling.iteration.fields names them.
  std::span<const ExchangedFieldKind> exchanges = {};

  /// `provides` as Process::writes() starts its list: the one record of
  /// what the process always writes.
  std::vector<std::string> provided_fields() const { return {provides.begin(), provides.end()}; }
};

/// A module's settings in the scene (under `key`, Scene::sections): scenes
/// built in code (tests, benchmarks) set them here, and a scene without the
/// section reads the defaults.
template <class Settings>
Settings& section_settings(Scene& scene, Key<Settings> key) {
  return scene.sections.get_or_add(key);
}
template <class Settings>
const Settings& section_settings(const Scene& scene, Key<Settings> key) {
  static const Settings defaults;
  const Settings* settings = scene.sections.find(key);
  return settings ? *settings : defaults;
}

/// A section a scene may have: the reader, and the physics that needs it
/// (listed under `physics`; empty for a section of its own, such as a block
/// source). A listed physics requires its section, and a section requires
/// its physics to be listed.
struct SceneSection {
  std::string_view physics;
  const SectionReader* reader = nullptr;
};

/// The sections of the process registry (coupling/process_registry.h
/// installs them before main, so that scenes built in code are asked the
/// same way as scenes read from a file).
void install_scene_sections(std::span<const SceneSection> sections);

/// Whether a process that `scene` switches on provides the shared `field`
/// (SectionReader::provides): how a module asks whether, say, the contacts
/// or the fracture flow it reads will be there, without naming the module
/// that writes them.
bool provides(const Scene& scene, std::string_view field);

}  // namespace fissure
