// Internal to core/scene: the scene while it is read, plus what the checks
// after reading need (where each block's geometry is written, which points
// still have to be attached to blocks). parse_scene.cpp runs the steps in the
// order they are declared here.
#pragma once

#include <optional>
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

struct SceneDraft {
  Scene scene;
  bool physics_read = false;  ///< `physics` was read as a list; consistency checks can use it

  NameRegistry materials{"material"};
  NameRegistry joints{"joint"};
  NameRegistry blocks{"block"};

  std::vector<BlockSource> block_sources;
  std::vector<PointToResolve> points;

  /// Where the `rock_mass` key is, and whether its section was read without
  /// a problem (only then are blocks generated from it).
  SourceLocation rock_mass_at;
  bool rock_mass_valid = false;
};

// Reading, one group of top-level keys per function.
void read_general(ConfigMap& top, SceneDraft& draft);      ///< name, physics, gravity
void read_materials(ConfigMap& top, SceneDraft& draft);    ///< materials, joints, default_joint
void read_blocks(ConfigMap& top, SceneDraft& draft);       ///< blocks
void read_rock_mass(ConfigMap& top, SceneDraft& draft);    ///< rock_mass (read_rock_mass.cpp)
void read_points(ConfigMap& top, SceneDraft& draft);       ///< fixed_points, point_loads, monitors
void read_mechanics(ConfigMap& top, SceneDraft& draft);    ///< mechanics
void read_flow(ConfigMap& top, SceneDraft& draft);         ///< flow (read_flow.cpp)
void read_time_output(ConfigMap& top, SceneDraft& draft);  ///< time, output

// Generation: the blocks and fracture graph of a valid `rock_mass` section,
// appended to the blocks read (generate_blocks.cpp). A missing generator or a
// generator error is reported at the `rock_mass` key.
void generate_rock_mass_blocks(SceneDraft& draft, const RockMassGenerator& generator,
                               Diagnostics& diagnostics);

// Checks on what was read.
/// Block polygons (check_polygon), orientation (orient_loops) and blocks that
/// overlap at the start. Returns the geometric tolerance used.
double check_geometry(SceneDraft& draft, Diagnostics& diagnostics);
/// Attaches fixed points, load points and monitors to blocks (locate_point).
void resolve_points(SceneDraft& draft, double tolerance, Diagnostics& diagnostics);

/// Geometric tolerance: 1e-9 x the largest extent of the bounding box of all
/// blocks (docs/scene-reference.md, "Geometry checks").
inline constexpr double kRelativeGeometryTolerance = 1e-9;

}  // namespace fissure
