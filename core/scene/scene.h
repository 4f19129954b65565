// The typed, validated scene: what a scene YAML file says, in SI units, with
// every cross reference resolved to an index. Produced by core/scene
// (parse_scene), consumed by the coordinator and the processes. Every member
// maps to one documented YAML key (docs/scene-reference.md); the only computed
// members are the blocks and fracture graph generated from a `rock_mass`
// section (mechanics/blocks, deterministic for a given seed).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/polygon.h"
#include "core/linear/linear_solver_controls.h"
#include "core/scene/flow_controls.h"
#include "core/scene/rock_mass_spec.h"
#include "core/state/fracture_graph.h"

namespace fissure {

/// Where a value came from, for messages: "scene.yaml:12:5".
struct SourceLocation {
  std::string file;
  int line = 0;    ///< 1-based; 0 when unknown
  int column = 0;  ///< 1-based
};

enum class PlaneMode { Stress, Strain };

struct Material {
  std::string name;
  double density = 0;        ///< kg/m^3
  double young_modulus = 0;  ///< Pa
  double poisson_ratio = 0;  ///< -
};

/// Mohr-Coulomb joint with tension cut-off (theory.md 1.4-1.5).
struct JointProperties {
  std::string name;
  double friction_angle = 0;    ///< rad
  double cohesion = 0;          ///< Pa
  double tensile_strength = 0;  ///< Pa
};

struct BlockSpec {
  std::string name;
  Polygon polygon;   ///< outer loop counter-clockwise, holes clockwise
  int material = 0;  ///< index into Scene::materials
  int joint = -1;    ///< index into Scene::joints, -1 = the default joint
  /// Joint of each edge v -> next(v), per vertex (index into Scene::joints;
  /// -1 = the block's joint). Empty: every edge has the block's joint.
  /// Filled for blocks generated from a rock mass (fracture joint per edge).
  std::vector<int> edge_joint;
  bool fixed = false;                                          ///< all six degrees of freedom held
  Eigen::Vector3d initial_stress = Eigen::Vector3d::Zero();    ///< sxx, syy, sxy (Pa, tension +)
  Eigen::Vector3d initial_velocity = Eigen::Vector3d::Zero();  ///< vx, vy (m/s), omega (rad/s)
  SourceLocation location;
};

/// A point held by a penalty spring (theory.md 1.3 "fixed point").
struct FixedPoint {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  int block = -1;  ///< resolved: the block that contains the point
  bool fix_x = true;
  bool fix_y = true;
};

/// Force that follows a material point. Optional piecewise-linear history
/// scales it in time (factor 1 when empty).
struct PointLoad {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  int block = -1;
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  ///< N (per unit thickness)
  std::vector<std::pair<double, double>> history;   ///< (t, factor), t increasing
};

struct Monitor {
  std::string name;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  int block = -1;  ///< block the point moves with; -1 = fixed in space
};

/// Shi's DDA controls (theory.md 1.7, 7.1).
struct DdaControls {
  double max_time_step = 1e-3;            ///< g1, s
  double max_displacement_ratio = 0.005;  ///< g2: max step displacement / half model size
  std::optional<double> penalty;          ///< g0, N/m; empty = automatic
  double penalty_factor = 50;             ///< automatic penalty = factor * max E * 1 m
  double shear_penalty_ratio = 1.0;       ///< p_s / p_n
  double velocity_carry_over = 1.0;       ///< k01: 1 dynamic, 0 static
  int max_open_close_iterations = 12;
  bool exact_rotation = true;  ///< geometry update without block inflation (theory.md 1.8)
  LinearSolverControls solver;
};

struct MechanicsControls {
  PlaneMode plane = PlaneMode::Strain;
  DdaControls dda;
};

struct TimeControls {
  double end_time = 0;     ///< s
  long max_steps = -1;     ///< -1 = no limit
  double min_step = 1e-9;  ///< s; a step cut below this ends the run as diverged
};

struct OutputControls {
  double interval = 0;   ///< s between output frames; 0 = every `every_steps` steps
  long every_steps = 0;  ///< used when interval is 0; 0 = first and last only
  bool hdf5 = true;      ///< write results.h5 / results.xdmf
};

struct Scene {
  std::string name;                                     ///< defaults to the file stem
  std::filesystem::path source;                         ///< the scene file
  std::vector<std::string> physics;                     ///< e.g. {"mechanics"}
  Eigen::Vector2d gravity = Eigen::Vector2d(0, -9.81);  ///< m/s^2

  std::vector<Material> materials;
  std::vector<JointProperties> joints;
  int default_joint = 0;  ///< used where a block names no joint

  std::vector<BlockSpec> blocks;  ///< the `blocks` list, then the generated blocks
  /// The `rock_mass` section, when given. Its blocks are generated at parse
  /// time and appended to `blocks`; its fracture graph is `fractures`.
  std::optional<RockMassSpec> rock_mass;
  /// Fracture network generated with the rock mass (block indices into
  /// `blocks`); empty without a rock mass.
  FractureGraph fractures;
  RockMassStatistics rock_mass_statistics;
  std::vector<FixedPoint> fixed_points;
  std::vector<PointLoad> point_loads;
  std::vector<Monitor> monitors;

  MechanicsControls mechanics;
  FlowControls flow;  ///< the `flow` section (flow/; docs/flow.md)
  TimeControls time;
  OutputControls output;

  bool has_physics(const std::string& p) const {
    for (const auto& q : physics)
      if (q == p) return true;
    return false;
  }
};

}  // namespace fissure
