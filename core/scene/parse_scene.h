// Reading and validating scene files (docs/architecture.md 3). Every problem found
// is reported, not just the first: each as "file:line:column: key: what was
// found; expected ...". Nothing runs on an invalid scene.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "core/scene/config_node.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"

namespace fissure {

/// Parses and validates a scene file: the shared keys here, every module's
/// section with the module's reader (`sections`, from the registry:
/// coupling/scene_sections.h reads a scene with every module). Throws
/// SceneError whose message lists every problem, one per line. A section
/// that no reader reads is an unknown key.
Scene parse_scene(const std::filesystem::path& file, std::span<const SceneSection> sections);

/// Same, from text; `file_name` is used in messages and for the scene name.
Scene parse_scene_text(const std::string& yaml, const std::string& file_name,
                       std::span<const SceneSection> sections);

// The YAML front that scenes and REV studies share.

/// The largest input file read (256 MB): a scene of 50 MB, a history of
/// 3 million points, is read in 3 GB and 20 s; what is larger is a mistake
/// (a wrong file, a device) far more often than a scene.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{256} << 20;

/// The text of an input file; throws SceneError "FILE:1:1: (document): found
/// no readable file; expected `what`" when it cannot be read, and likewise
/// for a folder, a device (/dev/zero: at once) and a file or pipe longer
/// than kMaxInputFileBytes (without reading more than that).
std::string read_input_file(const std::filesystem::path& file, std::string_view what);

/// The one YAML document in `yaml` as a tracked node; syntax errors and a
/// second document ("expected one `what` per file") are reported to
/// `diagnostics` (nothing is returned then).
std::optional<ConfigNode> load_document(const std::string& yaml, std::string_view what,
                                        Diagnostics& diagnostics);

}  // namespace fissure
