// The `rock_mass` section of a scene (docs/scene-reference.md section 5 and
// docs/rock-mass.md): the domain, excavations, joint sets, stochastic DFN
// families and explicit fractures from which the blocks and the fracture
// graph are generated. Values are in SI units, angles in radians, references
// resolved to indices; everything is validated by the reader
// (read_rock_mass.h). The generation itself (generate_rock_mass.h) runs when
// the scene is read, after every section.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/polygon.h"

namespace fissure {

/// A region removed from the rock (a tunnel, a cutting): a simple loop,
/// counter-clockwise. It may reach outside the domain.
struct ExcavationSpec {
  std::string name;
  std::vector<Vec2> vertices;
};

/// A probability distribution of one scalar: fracture orientations (rad),
/// trace lengths (m) or apertures (m). Which members are used depends on the
/// type; docs/rock-mass.md gives the densities.
struct DistributionSpec {
  enum class Type {
    Constant,           ///< `value` (orientation: "fixed")
    Uniform,            ///< lengths: [min, max]; orientations: all directions
    Exponential,        ///< lengths: `mean`
    LogNormal,          ///< lengths, apertures: `mean`, `std` of the value itself
    TruncatedPowerLaw,  ///< lengths: p(l) ~ l^-exponent on [min, max]
    VonMises,           ///< orientations: axial von Mises, `mean`, `kappa`
    LengthCorrelated,   ///< apertures: factor * (l / 1 m)^exponent
  };
  Type type = Type::Constant;
  double value = 0;
  double min = 0, max = 0;
  double mean = 0, std = 0;
  double exponent = 0;
  double kappa = 0;
  double factor = 0;
};

/// A set of parallel joints (Shi's DL): straight traces at dip `dip`, normal
/// spacing `spacing` (+- spread), cut into joints of `trace_length` separated
/// by rock bridges of `bridge_length` along each trace line.
struct JointSetSpec {
  std::string name;
  double dip = 0;                      ///< rad, trace direction from +x, counter-clockwise
  double spacing = 0;                  ///< m
  double spacing_spread = 0;           ///< m; each spacing uniform in [s - spread, s + spread]
  std::optional<double> trace_length;  ///< m; empty = fully persistent traces
  double bridge_length = 0;            ///< m
  double phase = 0;                    ///< offset of the lines, fraction of the spacing
  std::optional<double> stagger;  ///< shift between lines, fraction of the period; empty = random
  int joint = -1;                 ///< index into Scene::joints; -1 = the default joint
  double aperture = 0;            ///< m (hydraulic aperture e0)
};

/// One family of a stochastic discrete fracture network: a Poisson process
/// of straight fractures with random orientation, length and aperture.
struct DfnFamilySpec {
  enum class Density { P20, P21 };
  std::string name;
  Density density_kind = Density::P21;
  double density = 0;  ///< P20: fracture centres per m^2; P21: trace length per m^2 (1/m)
  DistributionSpec orientation, length, aperture;
  int joint = -1;  ///< index into Scene::joints; -1 = the default joint
};

/// A fracture given by its end points (clipped to the rock).
struct FractureSpec {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  int joint = -1;
  double aperture = 0;  ///< m
};

/// Which generated blocks are fixed.
struct FixedBlockRule {
  std::vector<std::string> boundaries;  ///< blocks with an edge on any of these boundaries
  std::optional<double> below;          ///< blocks whose centroid lies below this height (m)
};

struct RockMassSpec {
  std::vector<Vec2> domain;  ///< outer boundary, simple, counter-clockwise
  std::vector<ExcavationSpec> excavations;
  int material = 0;        ///< index into Scene::materials
  std::uint64_t seed = 1;  ///< of every random choice (joint sets and DFN)
  std::vector<JointSetSpec> joint_sets;
  std::vector<DfnFamilySpec> dfn;
  std::vector<FractureSpec> fractures;
  double merge_tolerance = 0;  ///< m (resolved: default 1e-5 x domain extent)
  // Defaults that keep `fissure validate` of the densest rock mass they admit
  // well within 10 s and 2 GB (issue 35; docs/rock-mass.md section 5: at
  // most 3.3 CPU s and 0.4 GB at either limit). Larger models set them.
  long max_blocks = 50000;
  long max_fractures = 100000;
  FixedBlockRule fixed;
  /// In-situ stress of every block [sxx, syy, sxy] (Pa, tension +).
  Eigen::Vector3d initial_stress = Eigen::Vector3d::Zero();
};

/// What the generation reports (summary.json of `fissure mesh`, docs).
struct RockMassStatistics {
  long estimated_blocks = 0;      ///< the estimate checked against max_blocks
  long generated_fractures = 0;   ///< traces generated (joint sets + DFN + explicit)
  long cut_fractures = 0;         ///< traces that reach the rock
  int slivers_merged = 0;         ///< faces thinner than the tolerance merged into a neighbour
  int vertices_merged = 0;        ///< vertices merged into a neighbour closer than the tolerance
  int invalid_merged = 0;         ///< faces merged because they were not simple polygons
  double generation_seconds = 0;  ///< joint sets and DFN
  double cutting_seconds = 0;     ///< arrangement, merging, blocks, fracture graph
};

/// Where the scene keeps the section and what its generation reported
/// (Scene::sections).
inline constexpr Key<RockMassSpec> kRockMassSpec{"rock_mass"};
inline constexpr Key<RockMassStatistics> kRockMassStatistics{"rock_mass.statistics"};

}  // namespace fissure
