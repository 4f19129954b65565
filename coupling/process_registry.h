// The one table of what Fissure's modules add to a scene (docs/architecture.md 7):
// each process's name (its name under `physics`), the section it reads and
// its factory; and the block sources (the rock mass), which read a section
// and generate blocks but do not advance in time. Adding a process means
// one folder plus one row here (docs/architecture.md "Adding a process").
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/results_part.h"
#include "core/process/process.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"

namespace fissure {

using ProcessFactory = std::unique_ptr<Process> (*)(const Scene&);

/// A row of the registry.
struct ProcessType {
  const char* name;              ///< under `physics`, in `coupling` and in the output
  const SectionReader* section;  ///< the section it reads
  ProcessFactory create;
};

/// Adds a process type after the registry's rows (a process built outside
/// it: a test's stand-in, docs/architecture.md "Adding a process"). Its
/// section is read and provides() answers for it from then on. A name
/// already taken is a logic_error.
void register_process_type(const ProcessType& type);

/// Every section a scene may have besides the shared keys: the block
/// sources' and the processes' (parse_scene's `sections`).
std::vector<SceneSection> scene_sections();

/// parse_scene / parse_scene_text with every module's section.
Scene read_scene(const std::filesystem::path& file);
Scene read_scene_text(const std::string& yaml, const std::string& file_name);

/// Every key a scene may hold, with its documented path ("name",
/// "materials[].density", "mechanics.dda.time_step", ...).
std::vector<std::string> known_scene_keys();

/// The physics names of the processes, in the registry's order.
std::vector<std::string> known_physics();

/// Builds the processes the scene activates, in the order they advance
/// (coupling.order, else the registry's order). They allocate nothing
/// before Process::initialize.
std::vector<std::unique_ptr<Process>> create_processes(const Scene& scene);

/// The one process `name` of the scene's physics (a stage that drives one
/// process itself, such as the REV study's mechanics, docs/upscaling.md);
/// SceneError when the scene does not list it.
std::unique_ptr<Process> create_process(const Scene& scene, std::string_view name);

/// The results parts of the shared fields that no process owns (the
/// fracture graph: written whenever the state has one).
std::vector<std::unique_ptr<ResultsPart>> shared_results_parts();

}  // namespace fissure
