// Reading and validating scene files (architecture.md 5). Every problem found
// is reported, not just the first: each as "file:line:column: key: what was
// found; expected ...". Nothing runs on an invalid scene.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace fissure {

/// The blocks and fracture graph generated from a scene's `rock_mass` section.
struct GeneratedRockMass {
  std::vector<BlockSpec> blocks;  ///< oriented (outer loop counter-clockwise, holes clockwise)
  FractureGraph fractures;        ///< block indices into `blocks`
  RockMassStatistics statistics;
};

/// Generates a rock mass (rockmass/generate_rock_mass.h). Throws
/// fissure::Error with a message that reads "what went wrong; expected what";
/// the parser reports it at the `rock_mass` key.
using RockMassGenerator = std::function<GeneratedRockMass(const RockMassSpec&)>;

/// Generators that a scene may need while it is parsed. They live in the
/// physics modules, which core must not depend on (architecture.md 1), so the
/// caller passes them in: `parse_scene(file, scene_generators())` with
/// rockmass/generate_rock_mass.h. Without a rock-mass generator a
/// scene with `rock_mass` is reported as an error.
struct SceneGenerators {
  RockMassGenerator rock_mass;
};

/// Parses and validates a scene file. Throws SceneError whose message lists
/// every problem, one per line.
Scene parse_scene(const std::filesystem::path& file, const SceneGenerators& generators = {});

/// Same, from text; `file_name` is used in messages and for the scene name.
Scene parse_scene_text(const std::string& yaml, const std::string& file_name,
                       const SceneGenerators& generators = {});

}  // namespace fissure
