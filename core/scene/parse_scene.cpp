// Reading a scene: load the YAML, read every section (collecting problems),
// check the geometry and attach points to blocks, then throw once with every
// problem, or return the validated Scene.
#include "core/scene/parse_scene.h"

#include <fstream>
#include <sstream>

#include "core/base/errors.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

/// The document, or nothing after reporting a syntax error.
std::optional<YAML::Node> load_yaml(const std::string& yaml, Diagnostics& diagnostics) {
  try {
    std::vector<YAML::Node> documents = YAML::LoadAll(yaml);
    if (documents.size() > 1) {
      const YAML::Mark m = documents[1].Mark();
      diagnostics.error(
          {diagnostics.file_name(), m.line >= 0 ? m.line + 1 : 1, m.line >= 0 ? m.column + 1 : 1},
          "", "found a second YAML document; expected one scene per file");
      return std::nullopt;
    }
    return documents.empty() ? YAML::Node() : documents.front();
  } catch (const YAML::Exception& e) {  // syntax errors, nesting too deep, ...
    diagnostics.error({diagnostics.file_name(), e.mark.line + 1, e.mark.column + 1}, "",
                      "found malformed YAML (" + e.msg + "); expected valid YAML syntax");
    return std::nullopt;
  }
}

}  // namespace

Scene parse_scene_text(const std::string& yaml, const std::string& file_name,
                       const SceneGenerators& generators) {
  Diagnostics diagnostics(file_name);
  const std::optional<YAML::Node> root = load_yaml(yaml, diagnostics);
  diagnostics.throw_if_any();

  SceneDraft draft;
  draft.scene.source = file_name;
  draft.scene.name = std::filesystem::path(file_name).stem().string();

  // 1. Read every section; each problem is recorded and reading goes on.
  const ConfigNode document = ConfigNode::root(*root, diagnostics);
  if (document.is_null()) {
    document.error("found an empty file; expected a scene (see docs/scene-reference.md)");
    diagnostics.throw_if_any();
  }
  {
    ConfigMap top(document, scene_keys::top);
    read_general(top, draft);
    read_materials(top, draft);
    read_blocks(top, draft);
    read_rock_mass(top, draft);
    read_points(top, draft);
    read_mechanics(top, draft);
    read_flow(top, draft);
    read_time_output(top, draft);
  }  // unknown top-level keys are reported here

  // 2. Blocks and fractures generated from the rock mass (mechanics/blocks),
  // appended to the blocks read.
  generate_rock_mass_blocks(draft, generators.rock_mass, diagnostics);

  // 3. Geometry, which needs all blocks: polygons, overlaps, points on blocks.
  const double tolerance = check_geometry(draft, diagnostics);
  resolve_points(draft, tolerance, diagnostics);

  // 4. Nothing may run on an invalid scene.
  diagnostics.throw_if_any();
  return std::move(draft.scene);
}

Scene parse_scene(const std::filesystem::path& file, const SceneGenerators& generators) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw SceneError(file.string() + ":1:1: (document): found no readable file; expected a " +
                     "scene file (YAML)");
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = parse_scene_text(text.str(), file.string(), generators);
  scene.source = file;
  return scene;
}

}  // namespace fissure
