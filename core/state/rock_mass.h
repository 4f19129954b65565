// The shared state that processes read and write (docs/architecture.md 4): the
// block system and the material points that move with blocks (monitors,
// load points, fixed points), which every module knows, and the named
// fields that processes exchange (`fields`: the fracture graph, contacts,
// pressures, ...), each defined by the module that owns its type and
// declared by the processes that read or write it (Process::reads, writes).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/polygon.h"
#include "core/scene/scene.h"

namespace fissure {

using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;

struct Block {
  std::string name;
  Polygon polygon;                     ///< current geometry
  std::vector<Vec2> initial_vertices;  ///< geometry at t = 0 (for displacements)
  std::vector<int> edge_joint;         ///< joint index of edge v -> next(v), per vertex
  int material = 0;
  bool fixed = false;

  SectionProperties section;  ///< area, centroid, central moments of `polygon`
  double initial_area = 0;    ///< area at t = 0: mass = density x initial_area is conserved
  Vector6 velocity = Vector6::Zero();  ///< rates of (u0, v0, r0, ex, ey, gxy)
  Vector3 stress = Vector3::Zero();    ///< sxx, syy, sxy (Pa, tension +)
  Vector3 strain = Vector3::Zero();    ///< accumulated ex, ey, gxy
  double rotation = 0;                 ///< accumulated rigid rotation (rad)
};

/// Density of a strained block: mass (density0 x initial area) is conserved
/// while the area changes with the strain.
inline double current_density(const Block& b, double density0) {
  return b.initial_area > 0 ? density0 * b.initial_area / b.section.area : density0;
}

/// A material point attached to a block (or fixed in space when block < 0).
struct MaterialPoint {
  int block = -1;
  Vec2 initial = Vec2::Zero();
  Vec2 current = Vec2::Zero();
};

/// Names of the blocks' state as the processes declare it (Process::reads,
/// writes): their geometry, their velocities, their stresses.
namespace block_fields {
inline constexpr std::string_view geometry = "block_geometry";
inline constexpr std::string_view kinematics = "block_kinematics";
inline constexpr std::string_view stress = "block_stress";
}  // namespace block_fields

struct RockMass {
  std::vector<Material> materials;
  std::vector<JointProperties> joints;
  Vec2 gravity = Vec2::Zero();

  std::vector<Block> blocks;
  /// Material points: the scene's monitors first, then its fixed points, then
  /// its point-load points, each in scene order.
  std::vector<MaterialPoint> points;
  int first_fixed_point = 0;
  int first_load_point = 0;

  /// The fields processes exchange, by name (named_values.h).
  NamedValues fields;

  double time = 0;

  /// Build the initial state from a validated scene (its blocks, points and
  /// initial fields).
  static RockMass from_scene(const Scene& scene);
};

}  // namespace fissure
