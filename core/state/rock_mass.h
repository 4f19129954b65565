// The shared state that processes read and write (architecture.md 1): the
// block system, its contacts and the material points that move with blocks
// (monitors, load points, fixed points). Later modules add the fracture graph,
// pressures and temperatures here.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/geometry/polygon.h"
#include "core/scene/scene.h"
#include "core/state/fracture_graph.h"

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

enum class ContactState : int { Open = 0, Sliding = 1, Locked = 2 };

/// A contact as the output and the other processes see it.
struct ContactRecord {
  int block_i = -1;  ///< block of the vertex
  int block_j = -1;  ///< block of the edge
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  ///< unit normal of the edge, pointing out of block_j
  ContactState state = ContactState::Open;
  double gap = 0;           ///< normal distance, < 0 penetration (m)
  double normal_force = 0;  ///< compressive > 0 (N per unit thickness)
  double shear_force = 0;   ///< along the edge tangent (N)
  int vertex = -1;          ///< the vertex: block_i's polygon vertex index
  int edge = -1;            ///< the edge: block_j's polygon edge edge -> next(edge)
};

/// Fluid pressure on a stretch a -> b of a block's edge (theory.md 3.5),
/// linear from p_a to p_b (Pa, compression positive), written by the flow
/// process and assembled by the mechanics as
///   F_i += -int p T_i^T n ds = -L/6 [(2 p_a + p_b) T_i(a)^T + (p_a + 2 p_b) T_i(b)^T] n
/// with n the block's outward unit normal there (start-of-step geometry).
struct EdgePressureLoad {
  int block = -1;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  double p_a = 0, p_b = 0;
  Vec2 normal = Vec2::Zero();
};

/// Flow state on RockMass::fractures (written by flow/; empty without flow).
struct FractureFlowState {
  std::vector<double> pressure;    ///< per node, Pa
  std::vector<double> aperture_a;  ///< per segment: hydraulic aperture at node_a, m
  std::vector<double> aperture_b;  ///< per segment: hydraulic aperture at node_b, m
  std::vector<double> flux;        ///< per segment, node_a -> node_b, m^2/s (per unit thickness)
};

struct RockMass {
  std::vector<Material> materials;
  std::vector<JointProperties> joints;
  PlaneMode plane = PlaneMode::Strain;
  Vec2 gravity = Vec2::Zero();

  std::vector<Block> blocks;
  std::vector<ContactRecord> contacts;
  /// Fracture network of the rock mass (empty unless the scene generates one
  /// or a process builds it).
  FractureGraph fractures;
  FractureFlowState flow;
  /// Fluid pressure loads on block edges (flow -> mechanics, theory.md 3.5).
  std::vector<EdgePressureLoad> pressure_loads;
  /// Material points: the scene's monitors first, then its fixed points, then
  /// its point-load points, each in scene order.
  std::vector<MaterialPoint> points;
  int first_fixed_point = 0;
  int first_load_point = 0;

  double time = 0;

  /// Build the initial state from a validated scene.
  static RockMass from_scene(const Scene& scene);
};

}  // namespace fissure
