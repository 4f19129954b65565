// The scene's `continuum` section (docs/scene-reference.md section 13,
// docs/continuum.md): the domain and its regions, the materials'
// poro-thermo-elastic properties, the mesh, the fluid, the initial state
// and the solution scheme; its conditions and sources are read by
// read_continuum_conditions.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "continuum/poroelasticity/continuum_exchanged_fields.h"
#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "continuum/poroelasticity/read_continuum_conditions.h"
#include "core/geometry/polygon.h"
#include "core/geometry/polygon_checks.h"
#include "core/scene/config_map.h"
#include "core/scene/parse_scene.h"
#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_keys.h"
#include "core/scene/scene_relative_file.h"
#include "core/scene/time_limits.h"
#include "rockmass/heat_keys.h"

namespace fissure {

namespace {

constexpr std::string_view kContinuum[] = {
    "domain",    "material",       "regions",     "materials", "mesh",
    "fluid",     "initial",        "conditions",  "scheme",    "fixed_stress_factor",
    "tolerance", "max_iterations", "time_step",   "geometry",  "sources",
    "holes",     "boundaries",     "time_scheme", "elements",  "pressure_stabilization",
    "solver"};
constexpr std::string_view kHole[] = {"name", "polygon"};
constexpr std::string_view kLine[] = {"name", "line"};
constexpr std::string_view kMaterial[] = {
    "name",         "biot_coefficient",  "biot_modulus",
    "permeability", "thermal_expansion", "fluid_thermal_expansion",
    "conductivity", "heat_capacity"};
constexpr std::string_view kRegion[] = {"name", "polygon", "material"};
constexpr std::string_view kMesh[] = {"divisions", "element_size", "fine_element_size",
                                      "size_grading", "max_elements"};
constexpr std::string_view kFluid[] = {"viscosity", "density"};
constexpr std::string_view kInitial[] = {
    "stress",      "stress_gradient",      "pressure",    "pressure_gradient",
    "temperature", "temperature_gradient", "reference_y", "undrained_start"};
const KeyTable continuum_table{"continuum", kContinuum};
const KeyTable material_table{"continuum.materials[]", kMaterial};
const KeyTable region_table{"continuum.regions[]", kRegion};
const KeyTable mesh_table{"continuum.mesh", kMesh};
const KeyTable fluid_table{"continuum.fluid", kFluid};
const KeyTable initial_table{"continuum.initial", kInitial};
const KeyTable hole_table{"continuum.holes[]", kHole};
const KeyTable line_table{"continuum.boundaries[]", kLine};
const KeyTable solver_table{"continuum.solver", scene_keys::refined_linear_solver};
// The map forms of a permeability: a `fissure rev` study's tensor (rev,
// size), a law of the stress (law, ...) or a stress study's table
// (stress_study, states).
constexpr std::string_view kPermeabilityForms[] = {
    "rev",   "size",  "stress_study", "states",           "law",
    "k_max", "k_min", "angle",        "reference_stress", "coefficient"};
const KeyTable permeability_table{"continuum.materials[].permeability", kPermeabilityForms};
const KeyTable* const kTables[] = {&continuum_table,
                                   &material_table,
                                   &region_table,
                                   &mesh_table,
                                   &fluid_table,
                                   &initial_table,
                                   &continuum::kConditionTable,
                                   &continuum::kPlateTable,
                                   &continuum::kSourceTable,
                                   &hole_table,
                                   &line_table,
                                   &permeability_table,
                                   &solver_table,
                                   &continuum::kHeatTransferTable};

/// The (kind) values of a tension-positive [xx, yy, xy] list.
std::optional<Eigen::Vector3d> three(const ConfigNode& node, const QuantityKind& kind,
                                     std::string_view what) {
  const QuantityKind* kinds[] = {&kind, &kind, &kind};
  const auto v = node.numbers(kinds, what);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

/// Whether (kxx, kyy, kxy) is symmetric positive definite; reports at `node`.
bool positive_definite(const ConfigNode& node, const Eigen::Vector3d& k, std::string_view found) {
  if (k(0) > 0 && k(1) > 0 && k(0) * k(1) - k(2) * k(2) > 0) return true;
  node.error(
      fmt::format("found {}; expected a symmetric positive definite tensor [kxx, kyy, "
                  "kxy] (kxx > 0, kyy > 0, kxx kyy > kxy^2)",
                  found));
  return false;
}

/// A study's file named at `key` of `map` (relative to the scene's folder),
/// parsed, and its path; nullopt (reported) when absent or unreadable.
struct StudyFile {
  nlohmann::json json;
  std::string path;
};
std::optional<StudyFile> read_study_file(ConfigMap& map, std::string_view key,
                                         const std::filesystem::path& scene_file,
                                         std::string_view what) {
  std::optional<std::filesystem::path> path;
  if (auto n = map.required(key, what)) path = scene_relative_file(*n, scene_file, what);
  if (!path) return std::nullopt;
  try {
    return StudyFile{nlohmann::json::parse(read_input_file(*path, what)), path->string()};
  } catch (const std::exception& e) {
    map.optional(key)->error(
        fmt::format("cannot read {}: {}; expected {}", path->string(), e.what(), what));
    return std::nullopt;
  }
}

/// The mean tensor of a `fissure rev` study (its rev.json, docs/flow.md
/// "REV"): at the representative size, or at `size`.
void read_rev_permeability(ConfigMap& map, const std::filesystem::path& scene_file,
                           PoroMaterial& m) {
  const ConfigNode& node = map.node();
  double size = 0;
  map.read("size", size, quantity::length, Range::positive());
  const auto file =
      read_study_file(map, "rev", scene_file, "the rev.json that `fissure rev` writes");
  if (!file) return;
  const nlohmann::json& rev = file->json;
  const std::string& path = file->path;
  if (!(size > 0)) {
    if (!rev.contains("rev_size") || !rev["rev_size"].is_number()) {
      map.optional("rev")->error(fmt::format(
          "found no representative size in {} (rev_size is null: the study's criterion was "
          "not met); expected a study that reached it, or `size:` naming one of its sizes",
          path));
      return;
    }
    size = rev["rev_size"].get<double>();
  }
  for (const nlohmann::json& s : rev.value("sizes", nlohmann::json::array()))
    if (s.contains("size") && std::abs(s["size"].get<double>() - size) <= 1e-9 * size &&
        s.contains("mean_k") && s["mean_k"].is_object()) {
      const nlohmann::json& k = s["mean_k"];
      const Eigen::Vector3d tensor(k.value("xx", 0.0), k.value("yy", 0.0), k.value("xy", 0.0));
      if (positive_definite(node, tensor,
                            fmt::format("the tensor [{:g}, {:g}, {:g}] m^2 at {:g} m in {}",
                                        tensor(0), tensor(1), tensor(2), size, path)))
        m.permeability = tensor;
      return;
    }
  node.error(
      fmt::format("found no size {:g} m with a mean tensor in {}; expected one of the "
                  "study's sizes",
                  size, path));
}

/// `law: exponential` (permeability_law.h): k_max (m^2), k_min (default
/// k_max), angle of k_max from x, reference_stress (the mean effective
/// stress of k_max, k_min), coefficient beta (1/Pa; one, or [beta_max,
/// beta_min]).
void read_permeability_law(ConfigMap& map, PoroMaterial& m) {
  static constexpr std::string_view kLaws[] = {"exponential"};
  if (auto n = map.required("law", "the law's name: exponential")) n->choice(kLaws);
  Eigen::Vector2d k_ref(0, 0), beta(0, 0);
  double angle = 0, sigma_ref = 0;
  map.read_required("k_max", k_ref(0), quantity::permeability, Range::positive());
  k_ref(1) = k_ref(0);
  map.read("k_min", k_ref(1), quantity::permeability, Range::positive());
  if (k_ref(1) > k_ref(0))
    map.optional("k_min")->error(
        fmt::format("found k_min {:g} m^2 above k_max {:g} m^2; expected "
                    "k_min <= k_max",
                    k_ref(1), k_ref(0)));
  map.read("angle", angle, quantity::angle, Range::any());
  map.read("reference_stress", sigma_ref, quantity::stress, Range::non_negative());
  if (auto n = map.required("coefficient", "beta (1/Pa or 1/MPa): one, or [beta_max, beta_min]")) {
    if (n->is_list()) {
      const QuantityKind* kinds[] = {&quantity::stress_sensitivity, &quantity::stress_sensitivity};
      if (const auto v = n->numbers(kinds, "[beta_max, beta_min]")) beta = {(*v)[0], (*v)[1]};
    } else if (auto b = n->quantity(quantity::stress_sensitivity, Range::any())) {
      beta = {*b, *b};
    }
  }
  m.permeability_law = continuum::StressPermeabilityLaw::exponential(k_ref, beta, sigma_ref, angle);
}

/// `stress_study: stress.json` (and `states`): the table of a `fissure rev`
/// stress study (permeability_law.h, stress_study_table).
void read_study_law(ConfigMap& map, const std::filesystem::path& scene_file, PoroMaterial& m) {
  std::vector<int> states;
  if (auto n = map.optional("states"))
    if (const auto items = n->list("states (indices of the study's stress states)", true))
      for (const ConfigNode& item : *items)
        if (auto i = item.integer(0, 1000000)) states.push_back(static_cast<int>(*i));
  const auto study = read_study_file(map, "stress_study", scene_file,
                                     "the stress.json of a `fissure rev` stress study");
  if (!study) return;
  try {
    m.permeability_law = continuum::stress_study_table(study->json, states, study->path);
  } catch (const Error& e) {
    map.optional("stress_study")->error(e.what());
  }
}

void read_permeability(const ConfigNode& node, const std::filesystem::path& scene_file,
                       PoroMaterial& m) {
  if (node.is_map()) {
    ConfigMap map(node, permeability_table);
    if (map.contains("law"))
      read_permeability_law(map, m);
    else if (map.contains("stress_study"))
      read_study_law(map, scene_file, m);
    else
      read_rev_permeability(map, scene_file, m);
  } else if (node.is_list()) {
    const auto k = three(node, quantity::permeability, "[kxx, kyy, kxy]");
    if (k && positive_definite(node, *k, node.found())) m.permeability = *k;
  } else if (auto k = node.quantity(quantity::permeability, Range::positive())) {
    m.permeability = {*k, *k, 0};
  }
}

void read_materials(const ConfigNode& node, SectionContext& context, ContinuumControls& c,
                    const std::vector<bool>& used) {
  const Scene& scene = context.scene();
  c.materials.assign(scene.materials.size(), PoroMaterial{});
  std::vector<bool> given(scene.materials.size(), false);
  if (const auto items = node.list("materials {name, biot_modulus, permeability}", true)) {
    for (const ConfigNode& item : *items) {
      ConfigMap map(item, material_table);
      const std::optional<int> index = context.material_entry(map, given);
      PoroMaterial m;
      map.read("biot_coefficient", m.biot_coefficient, quantity::dimensionless,
               Range::open_closed(0, 1));
      map.read_required("biot_modulus", m.biot_modulus, quantity::stress, Range::positive());
      if (auto n = map.required("permeability",
                                "a permeability > 0 (m^2), [kxx, kyy, kxy], {rev: rev.json}, {law: "
                                "exponential, ...} or {stress_study: stress.json}"))
        read_permeability(*n, scene.source, m);
      map.read("thermal_expansion", m.thermal_expansion, quantity::thermal_expansion,
               Range::non_negative());
      map.read("fluid_thermal_expansion", m.fluid_thermal_expansion, quantity::thermal_expansion,
               Range::any());
      map.read("conductivity", m.conductivity, quantity::conductivity, Range::positive());
      map.read("heat_capacity", m.heat_capacity, quantity::heat_capacity, Range::positive());
      if (index) {
        const Material& s = scene.materials[*index];
        m.young_modulus = s.young_modulus;
        m.poisson_ratio = s.poisson_ratio;
        m.density = s.density;
        c.materials[*index] = m;
      }
    }
  }
  for (std::size_t i = 0; i < given.size(); ++i)
    if (used[i] && !given[i])
      node.error(
          fmt::format("found no entry for material '{}'; expected its biot_modulus and "
                      "permeability in continuum.materials",
                      scene.materials[i].name));
}

/// A closed polygon of at least 3 points that does not cross itself.
/// The most vertices of one continuum outline (the domain, a region, a
/// hole, a named line): the mesh resolves each of its segments, and a jagged
/// outline of 10,000 vertices made meshing run for minutes (fuzz case 230).
constexpr std::size_t kMostOutlineVertices = 2000;

/// False (reported) when `points` has more than kMostOutlineVertices.
bool within_outline_limit(const ConfigNode& node, const std::vector<Vec2>& points) {
  if (points.size() <= kMostOutlineVertices) return true;
  node.error(
      fmt::format("found an outline of {} vertices; expected at most {} (the mesh resolves "
                  "every segment of an outline; docs/scene-reference.md, \"Limits\")",
                  points.size(), kMostOutlineVertices));
  return false;
}

std::optional<std::vector<Vec2>> read_polygon(const ConfigNode& node) {
  auto points = node.points(quantity::length, true);
  if (!points || !within_outline_limit(node, *points)) return std::nullopt;
  Polygon polygon(*points);
  const double size = bounding_box(polygon).size().maxCoeff();
  const auto problems = check_polygon(polygon, kRelativeGeometryTolerance * size);
  if (!problems.empty()) {
    node.error(problems.front().what +
               "; expected a simple polygon: at least 3 distinct vertices, non-zero area, edges "
               "that do not cross");
    return std::nullopt;
  }
  orient_loops(polygon);
  return polygon.vertices;
}

void read_mesh(const ConfigNode& node, ContinuumControls& c) {
  ConfigMap map(node, mesh_table);
  c.mesh_path = node.located_path();
  if (auto n = map.optional("divisions")) {
    const QuantityKind* kinds[] = {&quantity::dimensionless, &quantity::dimensionless};
    if (auto d = n->numbers(kinds, "[nx, ny]")) {
      if ((*d)[0] >= 1 && (*d)[1] >= 1 && (*d)[0] <= 1e5 && (*d)[1] <= 1e5 &&
          (*d)[0] == std::floor((*d)[0]) && (*d)[1] == std::floor((*d)[1]))
        c.divisions = {static_cast<int>((*d)[0]), static_cast<int>((*d)[1])};
      else
        n->error(fmt::format("found {}; expected two whole numbers of cells in 1 to 100000",
                             n->found()));
    }
  }
  map.read("element_size", c.element_size, quantity::length, Range::positive());
  map.read("fine_element_size", c.fine_element_size, quantity::length, Range::positive());
  map.read("size_grading", c.size_grading, quantity::dimensionless, Range::closed(0.05, 2));
  if (c.element_size > 0 && c.fine_element_size > c.element_size)
    if (auto n = map.optional("fine_element_size"))
      n->error(fmt::format("found {}; expected at most element_size ({} m)", n->found(),
                           c.element_size));
  map.read("max_elements", c.max_elements, quantity::dimensionless, Range::closed(1, 1e9));
  if (c.divisions[0] > 0 && map.contains("element_size"))
    map.optional("element_size")
        ->error_at_key("found both divisions and element_size; expected one of them");
  if (c.divisions[0] == 0 && !(c.element_size > 0) && map.valid())
    map.report_missing("element_size", "an element size > 0 (m), or divisions: [nx, ny]");
}

void read_initial(const ConfigNode& node, ContinuumControls& c) {
  ConfigMap map(node, initial_table);
  if (auto n = map.optional("stress"))
    if (auto s = three(*n, quantity::stress, "[sxx, syy, sxy]")) c.initial_stress = *s;
  if (auto n = map.optional("stress_gradient")) {
    constexpr QuantityKind per_m{
        "stress gradient", {1, -2, -2, 0, 0}, "Pa/m, MPa/m", "Pa/m", 1, 1e12};
    if (auto s = three(*n, per_m, "[dsxx/dy, dsyy/dy, dsxy/dy]")) c.initial_stress_gradient = *s;
  }
  map.read("pressure", c.initial_pressure, quantity::pressure, Range::any());
  constexpr QuantityKind pressure_gradient{
      "pressure gradient", {1, -2, -2, 0, 0}, "Pa/m, MPa/m", "Pa/m", 1, 1e12};
  map.read("pressure_gradient", c.initial_pressure_gradient, pressure_gradient, Range::any());
  map.read("temperature", c.initial_temperature, quantity::temperature,
           heat_keys::temperature_range());
  map.read("temperature_gradient", c.initial_temperature_gradient, quantity::temperature_gradient,
           Range::any());
  map.read("reference_y", c.reference_y, quantity::length, Range::any());
  map.read("undrained_start", c.undrained_start);
}

/// The first of `points` outside `domain` (on its outline counts as
/// inside); none for an empty domain (reported where it was read).
std::optional<Vec2> outside_vertex(const std::vector<Vec2>& domain,
                                   const std::vector<Vec2>& points) {
  if (domain.empty()) return std::nullopt;
  const Polygon polygon(domain);
  const double tol = kRelativeGeometryTolerance * bounding_box(polygon).size().maxCoeff();
  for (const Vec2& v : points)
    if (locate_point(polygon, v, tol) < 0) return v;
  return std::nullopt;
}

/// A hole (closed, strictly inside the domain) or a named line of the
/// boundary (open, on the domain's outline); its name must be new.
void read_outline(const ConfigNode& item, bool hole, ContinuumControls& c,
                  std::vector<std::string>& names) {
  ConfigMap map(item, hole ? hole_table : line_table);
  NamedOutline o;
  if (auto n = map.required("name", "a name for the boundary conditions"))
    if (auto v = n->string("a name")) {
      if (std::find(names.begin(), names.end(), *v) != names.end())
        n->error(
            fmt::format("found the boundary name '{}' again; expected a name that no side, "
                        "hole or line has",
                        *v));
      o.name = *v;
      names.push_back(*v);
    }
  const Polygon domain(c.domain);
  const double tol =
      c.domain.empty() ? 0 : kRelativeGeometryTolerance * bounding_box(domain).size().maxCoeff();
  if (hole) {
    if (auto p = map.required("polygon", "the hole's polygon [[x, y], ...]"))
      if (auto poly = read_polygon(*p)) {
        for (const Vec2& v : *poly)
          if (!c.domain.empty() && locate_point(domain, v, tol) <= 0) {
            p->error(
                fmt::format("found a vertex [{:g}, {:g}] that is not strictly inside "
                            "continuum.domain; expected a hole inside the domain",
                            v.x(), v.y()));
            break;
          }
        o.points = *poly;
      }
  } else if (auto p = map.required("line",
                                   "the line's points [[x, y], ...] along the domain's "
                                   "outline")) {
    if (auto points = p->points(quantity::length, true);
        points && within_outline_limit(*p, *points)) {
      if (points->size() < 2) p->error("found one point; expected a line of at least two points");
      for (const Vec2& v : *points)
        if (!c.domain.empty() && locate_point(domain, v, tol) != 0) {
          p->error(
              fmt::format("found a point [{:g}, {:g}] that is not on the domain's outline; "
                          "expected a line along it",
                          v.x(), v.y()));
          break;
        }
      o.points = *points;
    }
  }
  (hole ? c.holes : c.boundaries).push_back(std::move(o));
}

void read_continuum(const ConfigNode& node, SectionContext& context) {
  Scene& scene = context.scene();
  ContinuumControls& c = scene.sections.set(continuum::kSettings, ContinuumControls{});
  ConfigMap map(node, continuum_table);
  c.mesh_path = node.located_path();
  c.conditions_path = node.located_path() + ".conditions";
  constexpr std::string_view kGeometries[] = {"plane_strain", "axisymmetric"};
  if (auto n = map.optional("geometry"))
    if (auto g = n->choice(kGeometries)) c.axisymmetric = *g == "axisymmetric";
  if (auto n = map.required("domain", "the domain's outer polygon [[x, y], ...]"))
    if (auto p = read_polygon(*n)) {
      c.domain = *p;
      if (c.axisymmetric)
        for (const Vec2& v : c.domain)
          if (v.x() < 0) {
            n->error(
                fmt::format("found a vertex at x = {:g} m; expected x = r >= 0 with "
                            "geometry: axisymmetric (the y axis is the axis of symmetry)",
                            v.x()));
            break;
          }
    }

  std::vector<bool> used(scene.materials.size(), false);
  if (auto n = map.optional("material")) {
    if (auto i = context.materials().resolve(*n)) c.material = *i;
  } else if (scene.materials.size() > 1) {
    map.report_missing("material", "the material of the domain (the scene has several)");
  }
  if (c.material < static_cast<int>(used.size())) used[c.material] = true;
  if (auto n = map.optional("regions"))
    if (auto items = n->list("regions {name, polygon, material}", false))
      for (const ConfigNode& item : *items) {
        ConfigMap r(item, region_table);
        ContinuumRegion region;
        if (auto name = r.required("name", "the region's name")) {
          if (auto s = name->string("a name")) region.name = *s;
        }
        if (auto p = r.required("polygon", "the region's polygon [[x, y], ...]"))
          if (auto poly = read_polygon(*p)) {
            region.polygon = *poly;
            // Its outline becomes mesh edges: a vertex outside the domain
            // would be a node of no element (a singular system), or an edge
            // crossing the outline (fuzz case 139 of issue 34).
            if (const auto outside = outside_vertex(c.domain, *poly))
              p->error(fmt::format(
                  "found a vertex [{:g}, {:g}] outside continuum.domain; expected a region "
                  "inside the domain (vertices on its outline allowed)",
                  outside->x(), outside->y()));
          }
        if (auto m = r.required("material", "the region's material"))
          if (auto i = context.materials().resolve(*m)) {
            region.material = *i;
            used[*i] = true;
          }
        c.regions.push_back(std::move(region));
      }
  if (auto n = map.required("materials", "the poro-elastic properties of each material"))
    read_materials(*n, context, c, used);
  if (auto n = map.required("mesh", "the mesh: {divisions: [nx, ny]} or {element_size: h}"))
    read_mesh(*n, c);
  if (auto n = map.optional("fluid")) {
    ConfigMap f(*n, fluid_table);
    f.read("viscosity", c.viscosity, quantity::viscosity, Range::positive());
    f.read("density", c.fluid_density, quantity::density, Range::non_negative());
  }
  if (auto n = map.optional("initial")) read_initial(*n, c);

  std::vector<std::string> boundaries(std::begin(continuum::kNamedSides),
                                      std::end(continuum::kNamedSides));
  if (auto n = map.optional("holes"))
    if (auto items = n->list("holes {name, polygon}", false))
      for (const ConfigNode& item : *items) read_outline(item, true, c, boundaries);
  if (auto n = map.optional("boundaries"))
    if (auto items = n->list("boundaries {name, line}", false))
      for (const ConfigNode& item : *items) read_outline(item, false, c, boundaries);
  if (auto n = map.optional("conditions"))
    if (auto items = n->list("conditions", false))
      for (const ConfigNode& item : *items) continuum::read_condition(item, boundaries, c);
  if (auto n = map.optional("sources"))
    if (auto items = n->list("sources {name, point, power | fluid_rate}", false))
      for (const ConfigNode& item : *items) continuum::read_source(item, c);

  if (auto n = map.optional("scheme"))
    if (auto s = n->choice(enum_names(ContinuumControls::kSchemeNames)))
      c.scheme = value_of(ContinuumControls::kSchemeNames, *s);
  constexpr std::string_view kElements[] = {"taylor_hood", "p1p1"};
  if (auto n = map.optional("elements"))
    if (auto e = n->choice(kElements)) c.linear_displacement = *e == "p1p1";
  constexpr std::string_view kTimeSchemes[] = {"backward_euler", "bdf2"};
  if (auto n = map.optional("time_scheme"))
    if (auto s = n->choice(kTimeSchemes))
      c.time_scheme = *s == "bdf2" ? ContinuumControls::TimeScheme::Bdf2
                                   : ContinuumControls::TimeScheme::BackwardEuler;
  map.read("pressure_stabilization", c.pressure_stabilization, quantity::dimensionless,
           Range::closed(0, 100));
  map.read("fixed_stress_factor", c.fixed_stress_factor, quantity::dimensionless,
           Range::closed(0, 100));
  map.read("tolerance", c.tolerance, quantity::dimensionless, Range::open(0, 1));
  map.read("max_iterations", c.max_iterations, 1);
  if (auto n = map.optional("solver")) {
    read_linear_solver(*n, solver_table, c.solver);
    if (c.solver.type == LinearSolverControls::Type::Pcg)
      n->error(
          "found solver type 'pcg', which is the fracture network's; expected auto, "
          "direct or petsc");
  }
  if (auto n = map.optional("time_step")) {
    if (auto dt = n->quantity(quantity::time, Range::positive())) {
      c.time_step = *dt;
      check_time_step(*n, *dt, scene.time);
    }
  }
  const bool alone =
      context.physics_read() && scene.physics.size() == 1 && scene.has_physics("continuum");
  if (alone && !map.contains("time_step"))  // a value that is there was checked above
    map.report_missing("time_step", "a time step > 0, because continuum is the only process");
}

}  // namespace

namespace continuum {
const SectionReader kContinuumSection{
    "continuum",
    "a continuum section, because physics lists continuum (see docs/continuum.md)",
    &read_continuum,
    nullptr,
    kTables,
    {},
    true,
    {},
    kExchangedFields};
}  // namespace continuum

}  // namespace fissure
