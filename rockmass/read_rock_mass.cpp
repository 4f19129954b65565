// The scene's `rock_mass` section: the domain, excavations, material, seed,
// explicit fractures, tolerances and the fixed-block rule (joint sets and DFN
// families are read in read_rock_mass_sets.cpp). The geometry is checked here,
// so that the generator only ever sees a valid description: a simple domain,
// simple excavations that reach into it, fractures that reach the rock. Once
// every section is read, the blocks and the fracture graph are generated.
#include <fmt/format.h>

#include <algorithm>

#include "core/geometry/domain_sides.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/segment_predicates.h"
#include "core/scene/joint_models.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/generate_rock_mass.h"
#include "rockmass/read_rock_mass.h"

namespace fissure {

namespace {

constexpr std::string_view kRockMass[] = {"domain",        "excavations",     "material",
                                          "seed",          "joint_sets",      "dfn",
                                          "fractures",     "merge_tolerance", "max_blocks",
                                          "max_fractures", "fixed_blocks",    "initial_stress"};
constexpr std::string_view kExcavation[] = {"name", "circle", "vertices"};
constexpr std::string_view kCircle[] = {"centre", "radius", "segments"};
constexpr std::string_view kJointSet[] = {
    "name",          "dip",   "spacing", "spacing_spread", "trace_length",
    "bridge_length", "phase", "stagger", "joint",          "aperture"};
constexpr std::string_view kDfnFamily[] = {"name",   "density",  "orientation",
                                           "length", "aperture", "joint"};
constexpr std::string_view kDensity[] = {"p20", "p21"};
constexpr std::string_view kOrientation[] = {"distribution", "value", "mean", "kappa"};
constexpr std::string_view kLength[] = {"distribution", "value", "min",     "max",
                                        "mean",         "std",   "exponent"};
constexpr std::string_view kAperture[] = {"distribution", "value",  "mean",
                                          "std",          "factor", "exponent"};
constexpr std::string_view kFracture[] = {"from", "to", "joint", "aperture"};
constexpr std::string_view kFixedBlocks[] = {"boundaries", "below"};

}  // namespace

namespace rock_mass_keys {
const KeyTable rock_mass{"rock_mass", kRockMass};
const KeyTable excavation{"rock_mass.excavations[]", kExcavation};
const KeyTable circle{"rock_mass.excavations[].circle", kCircle};
const KeyTable joint_set{"rock_mass.joint_sets[]", kJointSet};
const KeyTable dfn_family{"rock_mass.dfn[]", kDfnFamily};
const KeyTable dfn_density{"rock_mass.dfn[].density", kDensity};
const KeyTable dfn_orientation{"rock_mass.dfn[].orientation", kOrientation};
const KeyTable dfn_length{"rock_mass.dfn[].length", kLength};
const KeyTable dfn_aperture{"rock_mass.dfn[].aperture", kAperture};
const KeyTable fracture{"rock_mass.fractures[]", kFracture};
const KeyTable fixed_blocks{"rock_mass.fixed_blocks", kFixedBlocks};
}  // namespace rock_mass_keys

namespace {

const KeyTable* const kTables[] = {
    &rock_mass_keys::rock_mass,       &rock_mass_keys::excavation,  &rock_mass_keys::circle,
    &rock_mass_keys::joint_set,       &rock_mass_keys::dfn_family,  &rock_mass_keys::dfn_density,
    &rock_mass_keys::dfn_orientation, &rock_mass_keys::dfn_length,  &rock_mass_keys::dfn_aperture,
    &rock_mass_keys::fracture,        &rock_mass_keys::fixed_blocks};

/// Merge tolerance when none is given, relative to the domain's extent.
constexpr double kDefaultRelativeMergeTolerance = 1e-5;

double extent(const std::vector<Vec2>& loop) {
  Box box;
  for (const Vec2& p : loop) box.extend(p);
  return box.empty() ? 0 : box.size().maxCoeff();
}

/// A simple loop, stored counter-clockwise; problems reported at `node`.
bool check_loop(std::vector<Vec2>& loop, double tol, const ConfigNode& node,
                std::string_view what) {
  // Refused before any check: the crossing check and the cut are not linear
  // in the vertices of a jagged outline (a 100,000-vertex star took minutes).
  if (loop.size() > static_cast<std::size_t>(kMostVerticesPerBlock)) {
    node.error(
        fmt::format("found a polygon of {} vertices; expected {} of at most {} vertices "
                    "(its vertices become block vertices; docs/scene-reference.md, "
                    "\"Limits\")",
                    loop.size(), what, kMostVerticesPerBlock));
    return false;
  }
  Polygon polygon(loop);
  const std::vector<PolygonProblem> problems = check_polygon(polygon, tol);
  for (const PolygonProblem& p : problems)
    node.error(p.what + "; expected " + std::string(what) +
               ": a simple polygon with at least 3 distinct vertices, non-zero area, edges "
               "that do not cross");
  if (!problems.empty()) return false;
  if (signed_area(loop) < 0) std::reverse(loop.begin() + 1, loop.end());
  return true;
}

void read_excavations(const ConfigNode& node, const std::vector<Vec2>* domain, double tol,
                      RockMassSpec& spec) {
  const std::optional<ConfigList> items = node.list("excavations", false);
  if (!items) return;
  NameRegistry names("excavation");
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, rock_mass_keys::excavation);
    ExcavationSpec e;
    if (auto n = map.required("name", "an excavation name (a boundary name of the rock mass)")) {
      if (auto name = n->string("an excavation name")) {
        if (*name == "left" || *name == "right" || *name == "bottom" || *name == "top")
          n->error("found '" + *name +
                   "', the name of a domain side; expected another excavation name");
        names.add(*name, *n);
        e.name = *name;
      }
    }
    std::optional<ConfigNode> circle = map.optional("circle");
    std::optional<ConfigNode> vertices = map.optional("vertices");
    if (circle && vertices) {
      vertices->error_at_key("found both `circle` and `vertices`; expected one of them");
      continue;
    }
    std::optional<std::vector<Vec2>> loop;
    const ConfigNode* at = nullptr;
    if (circle) {
      at = &*circle;
      ConfigMap c(*circle, rock_mass_keys::circle);
      std::optional<Vec2> centre;
      if (auto n = c.required("centre", "a point [x, y]")) centre = n->vec2(quantity::length);
      double radius = 0;
      c.read_required("radius", radius, quantity::length, Range::positive());
      int segments = 48;
      // At most a block's vertices (checked before the polygon is made).
      c.read("segments", segments, 3, kMostVerticesPerBlock);
      if (centre && radius > 0) loop = regular_polygon(*centre, radius, segments);
    } else if (vertices) {
      at = &*vertices;
      loop = vertices->points(quantity::length, true);
    } else {
      map.report_missing("circle", "a circle {centre, radius, segments} or a list `vertices`");
      continue;
    }
    if (!loop || !check_loop(*loop, tol, *at, "an excavation")) continue;
    // An excavation must take some rock away: its interior overlaps the domain.
    if (domain) {
      const Polygon both[] = {Polygon(*domain), Polygon(*loop)};
      if (find_overlapping_pairs(both, tol).empty()) {
        at->error("found an excavation outside the domain; expected one that overlaps it");
        continue;
      }
    }
    e.vertices = std::move(*loop);
    spec.excavations.push_back(std::move(e));
  }
}

/// True when the segment reaches the inside of `loop`.
bool reaches_inside(const Vec2& a, const Vec2& b, const std::vector<Vec2>& loop, double tol) {
  const Polygon polygon(loop);
  if (locate_point(polygon, a, tol) > 0 || locate_point(polygon, b, tol) > 0 ||
      locate_point(polygon, 0.5 * (a + b), tol) > 0)
    return true;
  const int n = static_cast<int>(loop.size());
  for (int k = 0; k < n; ++k)
    if (segments_cross(a, b, loop[k], loop[(k + 1) % n], tol)) return true;
  return false;
}

void read_fractures(const ConfigNode& node, const NameRegistry& joints,
                    const std::vector<Vec2>* domain, double tol, RockMassSpec& spec) {
  const std::optional<ConfigList> items = node.list("fractures", false);
  if (!items) return;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, rock_mass_keys::fracture);
    FractureSpec f;
    f.aperture = kDefaultAperture;
    std::optional<Vec2> from, to;
    if (auto n = map.required("from", "a point [x, y]")) from = n->vec2(quantity::length);
    if (auto n = map.required("to", "a point [x, y]")) to = n->vec2(quantity::length);
    if (auto j = map.optional("joint"))
      if (auto i = joints.resolve(*j)) f.joint = *i;
    map.read("aperture", f.aperture, quantity::length, aperture_range());
    if (!from || !to) continue;
    f.from = *from;
    f.to = *to;
    if ((f.to - f.from).norm() <= tol) {
      item.error("found a fracture of zero length; expected distinct `from` and `to`");
      continue;
    }
    if (domain && !reaches_inside(f.from, f.to, *domain, tol)) {
      item.error(
          fmt::format("found a fracture from ({}, {}) to ({}, {}), outside the domain; "
                      "expected a fracture that reaches into the domain",
                      f.from.x(), f.from.y(), f.to.x(), f.to.y()));
      continue;
    }
    spec.fractures.push_back(f);
  }
}

void read_fixed_blocks(const ConfigNode& node, const RockMassSpec& spec, bool geometry_read,
                       FixedBlockRule& rule) {
  ConfigMap map(node, rock_mass_keys::fixed_blocks);
  std::vector<std::string> known = domain_sides(spec.domain);
  for (const ExcavationSpec& e : spec.excavations) known.push_back(e.name);
  if (auto b = map.optional("boundaries")) {
    if (auto items = b->list("boundary names", true)) {
      for (const ConfigNode& item : *items) {
        const std::optional<std::string> name = item.string("a boundary name");
        if (!name) continue;
        if (geometry_read && std::find(known.begin(), known.end(), *name) == known.end()) {
          std::string list;
          for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
          item.error("found '" + *name + "'; expected a boundary of this rock mass: " +
                     (list.empty() ? std::string("(none)") : list));
          continue;
        }
        rule.boundaries.push_back(*name);
      }
    }
  }
  if (auto b = map.optional("below"))
    if (auto y = b->quantity(quantity::length)) rule.below = *y;
}

/// The in-situ stress against the joints of the rock mass's fractures (and
/// the default joint of its outline): each must hold it (Barton-Bandis:
/// below JCS; core/scene/joint_models.h).
void check_joints_hold(const ConfigNode& node, const RockMassSpec& spec, const Scene& scene) {
  std::vector<int> used = {scene.default_joint};
  for (const auto& s : spec.joint_sets) used.push_back(s.joint);
  for (const auto& f : spec.dfn) used.push_back(f.joint);
  for (const auto& f : spec.fractures) used.push_back(f.joint);
  for (int& j : used)
    if (j < 0) j = scene.default_joint;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (const int j : used)
    if (j >= 0 && j < static_cast<int>(scene.joints.size()))
      check_joint_stress_limit(node, spec.initial_stress, scene.joints[j]);
}

void read_rock_mass(const ConfigNode& node, SectionContext& context) {
  ConfigMap map(node, rock_mass_keys::rock_mass);
  RockMassSpec spec;

  // 1. The domain fixes the tolerance of every other geometric check.
  bool domain_ok = false;
  double tol = 0;
  if (auto d = map.required("domain", "a list of at least 3 vertices [x, y]")) {
    if (auto loop = d->points(quantity::length, true)) {
      tol = kRelativeGeometryTolerance * extent(*loop);
      domain_ok = check_loop(*loop, tol, *d, "a domain");
      spec.domain = std::move(*loop);
    }
  }
  const std::vector<Vec2>* domain = domain_ok ? &spec.domain : nullptr;

  if (auto e = map.optional("excavations")) read_excavations(*e, domain, tol, spec);

  // 2. Material, seed, the generators.
  if (auto m = map.optional("material")) {
    if (auto i = context.materials().resolve(*m)) spec.material = *i;
  } else if (context.scene().materials.size() > 1) {
    map.report_missing("material",
                       "the name of a material (required when the scene has more than one)");
  }
  if (auto s = map.optional("seed"))
    if (auto v = s->integer(0)) spec.seed = static_cast<std::uint64_t>(*v);

  NameRegistry sets("joint set or DFN family");
  if (auto j = map.optional("joint_sets"))
    if (auto items = j->list("joint sets", false))
      for (const ConfigNode& item : *items)
        spec.joint_sets.push_back(read_joint_set(item, context.joints(), sets));
  if (auto d = map.optional("dfn"))
    if (auto items = d->list("DFN families", false))
      for (const ConfigNode& item : *items)
        spec.dfn.push_back(read_dfn_family(item, context.joints(), sets));
  if (auto f = map.optional("fractures")) read_fractures(*f, context.joints(), domain, tol, spec);

  // 3. Tolerances and limits.
  const double domain_extent = domain ? extent(spec.domain) : 0;
  spec.merge_tolerance = kDefaultRelativeMergeTolerance * domain_extent;
  if (auto t = map.optional("merge_tolerance")) {
    // Well above the geometry tolerance (1e-9 x extent), well below the
    // domain: 1e-8 .. 1e-2 of the extent.
    const Range range =
        domain ? Range::closed(1e-8 * domain_extent, 1e-2 * domain_extent) : Range::positive();
    if (auto v = t->quantity(quantity::length, range)) spec.merge_tolerance = *v;
  }
  map.read("max_blocks", spec.max_blocks, 1);
  map.read("max_fractures", spec.max_fractures, 1);
  if (auto f = map.optional("fixed_blocks")) read_fixed_blocks(*f, spec, domain_ok, spec.fixed);
  if (auto node = map.optional("initial_stress")) {
    const QuantityKind* kinds[] = {&quantity::stress, &quantity::stress, &quantity::stress};
    if (auto s = node->numbers(kinds, "[sxx, syy, sxy]")) {
      spec.initial_stress = Eigen::Vector3d((*s)[0], (*s)[1], (*s)[2]);
      check_joints_hold(*node, spec, context.scene());
    }
  }
  context.scene().sections.set(kRockMassSpec, std::move(spec));
}

/// The blocks and the fracture graph; the graph's block indices count from
/// `first_block`, where the generated blocks start in Scene::blocks.
std::vector<BlockSpec> generate(SectionContext& context, int first_block) {
  Scene& scene = context.scene();
  GeneratedRockMass generated = generate_rock_mass(scene.sections.get(kRockMassSpec));
  for (FractureSegment& s : generated.fractures.segments)
    for (BlockFace* face : {&s.left, &s.right})
      if (face->block >= 0) face->block += first_block;
  scene.initial_fields.set(kFractureGraph, std::move(generated.fractures));
  scene.sections.set(kRockMassStatistics, generated.statistics);
  return std::move(generated.blocks);
}

}  // namespace

const SectionReader kRockMassSection{"rock_mass", "", &read_rock_mass, &generate, kTables};

}  // namespace fissure
