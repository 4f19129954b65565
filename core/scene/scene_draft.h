// Internal to core/scene: the scene while it is read, plus what the checks
// after reading need (where each block's geometry is written, which points
// still have to be attached to blocks). parse_scene.cpp runs the steps in the
// order they are declared here.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/scene/config_map.h"
#include "core/scene/name_registry.h"
#include "core/scene/parse_scene.h"
#include "core/scene/scene.h"

namespace fissure {

/// Where one block's geometry came from.
struct BlockSource {
  std::string path;            ///< "blocks[2]"
  SourceLocation vertices_at;  ///< the `vertices` key
  SourceLocation holes_at;     ///< the `holes` key (vertices_at when absent)
  bool geometry_read = false;  ///< every coordinate was read; the polygon can be checked
  bool polygon_valid = false;  ///< passed check_polygon (set by check_geometry)
};

/// A point (fixed point, load point, monitor) still to be attached to a block.
struct PointToResolve {
  enum class Owner { FixedPoint, PointLoad, Monitor };
  Owner owner = Owner::FixedPoint;
  int index = 0;                     ///< into the owner's list in Scene
  std::string path;                  ///< "fixed_points[0]"
  SourceLocation point_at;           ///< the `point` value
  std::optional<Vec2> point;         ///< empty when it could not be read
  std::optional<std::string> block;  ///< the `block` key, when given
  std::optional<ConfigNode> block_node;
};

/// A block source's section that was read without a problem: it generates
/// its blocks once every section has been read.
struct PendingBlockSource {
  const SectionReader* reader = nullptr;
  SourceLocation key_at;  ///< where its key is: generation errors are reported there
};

struct SceneDraft {
  Scene scene;
  bool physics_read = false;  ///< `physics` was read as a list; consistency checks can use it
  ConfigMap* top = nullptr;   ///< the document's map, while it is read

  NameRegistry materials{"material"};
  NameRegistry joints{"joint"};
  NameRegistry blocks{"block"};

  std::vector<BlockSource> block_sources;
  std::vector<PointToResolve> points;
  std::vector<PendingBlockSource> pending_block_sources;
};

// Reading, one group of top-level keys per function.
void read_general(ConfigMap& top, SceneDraft& draft,
                  std::span<const SceneSection> sections);  ///< name, physics, gravity
void read_materials(ConfigMap& top, SceneDraft& draft);     ///< materials, joints, default_joint
/// blocks; `other_sources`: the sections present that generate blocks or
/// bring their own geometry ("rock_mass"), which make `blocks` optional.
void read_blocks(ConfigMap& top, SceneDraft& draft,
                 const std::vector<std::string_view>& other_sources);
void read_points(ConfigMap& top, SceneDraft& draft);       ///< fixed_points, point_loads, monitors
void read_coupling(ConfigMap& top, SceneDraft& draft);     ///< coupling
void read_time_output(ConfigMap& top, SceneDraft& draft);  ///< time, output
/// A module's section (scene_section.h): read when present, and checked
/// against `physics`.
void read_module_section(ConfigMap& top, SceneDraft& draft, const SceneSection& section);

// Generation: the blocks of every block source that was read without a
// problem, appended to the blocks read (generate_blocks.cpp). A generator
// error is reported at the source's key.
void generate_blocks(SceneDraft& draft, Diagnostics& diagnostics);

// Checks on what was read.
/// Block polygons (check_polygon), orientation (orient_loops) and blocks that
/// overlap at the start. Returns the geometric tolerance used.
double check_geometry(SceneDraft& draft, Diagnostics& diagnostics);
/// Attaches fixed points, load points and monitors to blocks (locate_point).
void resolve_points(SceneDraft& draft, double tolerance, Diagnostics& diagnostics);

}  // namespace fissure
