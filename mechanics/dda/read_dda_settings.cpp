// The scene's `mechanics` section: method, plane mode and Shi's DDA controls
// (theory.md 1.7, 7.1). Every contact needs a joint law, so the DDA also
// needs the scene's joints.
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_keys.h"
#include "core/scene/scene_relative_file.h"
#include "core/scene/time_limits.h"
#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_settings.h"
#include "mechanics/dda/ground_motion_file.h"

#include "rockmass/fields/contacts.h"
#include "rockmass/fields/interface_ties.h"

namespace fissure {

namespace {

using dda::format_of;
using dda::GroundMotionRecord;
using dda::kMotionQuantityNames;
using dda::kRecordFormatNames;
using dda::MotionQuantity;
using dda::quantity_of;
using dda::read_peer_at2;
using dda::read_record_columns;
using dda::RecordColumn;
using dda::RecordColumns;
using dda::RecordFileError;
using dda::RecordFormat;

constexpr std::string_view kMechanics[] = {"method", "plane", "dda", "ground_motion",
                                           "viscous_boundaries"};
constexpr std::string_view kDda[] = {"time_step",
                                     "max_displacement_ratio",
                                     "penalty",
                                     "penalty_factor",
                                     "shear_penalty_ratio",
                                     "velocity_carry_over",
                                     "damping_ratio",
                                     "max_open_close_iterations",
                                     "exact_rotation",
                                     "solver",
                                     "contact_method",
                                     "penetration_tolerance",
                                     "max_augmentations",
                                     "ejection_speed"};
const KeyTable mechanics_table{"mechanics", kMechanics};
const KeyTable dda_table{"mechanics.dda", kDda};
const KeyTable solver_table{"mechanics.dda.solver", scene_keys::linear_solver};
constexpr std::string_view kGroundMotion[] = {
    "file",  "format", "quantity",      "unit",  "scale",
    "x",     "y",      "vertical_file", "start", "baseline_correction",
    "blocks"};
const KeyTable ground_motion_table{"mechanics.ground_motion", kGroundMotion};
constexpr std::string_view kViscousBoundary[] = {"line", "material", "free_field"};
const KeyTable viscous_table{"mechanics.viscous_boundaries[]", kViscousBoundary};
const KeyTable* const kTables[] = {&mechanics_table, &dda_table, &solver_table,
                                   &ground_motion_table, &viscous_table};

void read_dda(const ConfigNode& node, DdaControls& dda, const TimeControls& time,
              bool pseudo_time) {
  ConfigMap map(node, dda_table);
  if (auto step = map.optional("time_step"))
    if (auto dt = step->quantity(quantity::time, Range::positive())) {
      dda.max_time_step = *dt;
      if (!pseudo_time) check_time_step(*step, *dt, time);
    }
  map.read("max_displacement_ratio", dda.max_displacement_ratio, quantity::dimensionless,
           Range::open(0, 1));
  if (auto p = map.optional("penalty")) {
    if (p->is_scalar() && p->text() == "auto") {
      dda.penalty.reset();
    } else if (p->is_scalar() && !p->text().empty() &&
               std::isalpha(static_cast<unsigned char>(p->text()[0]))) {
      p->error("found " + p->found() + "; expected 'auto' or " +
               expectation(quantity::stiffness, Range::positive()));
    } else if (auto value = p->quantity(quantity::stiffness, Range::positive())) {
      dda.penalty = *value;
    }
  }
  map.read("penalty_factor", dda.penalty_factor, quantity::dimensionless, Range::positive());
  map.read("shear_penalty_ratio", dda.shear_penalty_ratio, quantity::dimensionless,
           Range::open_closed(0, 10));
  map.read("velocity_carry_over", dda.velocity_carry_over, quantity::dimensionless,
           Range::closed(0, 1));
  map.read("damping_ratio", dda.damping_ratio, quantity::dimensionless, Range::closed_open(0, 1));
  // At most 1,000: a step that needs more is cut anyway (at 12 by default),
  // and 1e6 would keep one step busy for minutes.
  map.read("max_open_close_iterations", dda.max_open_close_iterations, 1, 1000);
  map.read("exact_rotation", dda.exact_rotation);
  if (auto m = map.optional("contact_method"))
    if (auto method = m->choice(enum_names(kContactMethodNames)))
      dda.contact_method = value_of(kContactMethodNames, *method);
  if (auto t = map.optional("penetration_tolerance"))
    if (auto v = t->quantity(quantity::length, Range::positive())) dda.penetration_tolerance = *v;
  map.read("max_augmentations", dda.max_augmentations, 1, 1000);
  map.read("ejection_speed", dda.ejection_speed, quantity::velocity, Range::positive());
  if (auto s = map.optional("solver")) read_linear_solver(*s, solver_table, dda.solver);
}

/// `x` or `y` of a csv or columns record: a header name, a column number
/// (the time is column 1) or `none`.
RecordColumn read_column(ConfigMap& map, std::string_view key, RecordFormat format) {
  RecordColumn c;
  const std::optional<ConfigNode> node = map.optional(key);
  if (!node) return c;
  if (format == RecordFormat::PeerAt2) {
    node->error_at_key(
        "found a column for a PEER AT2 file; expected no column (an AT2 file "
        "holds one component: give the vertical one as vertical_file)");
  } else if (node->is_scalar() && node->text() == "none") {
    if (key == "x")  // reported; the record is read with its default x column
      node->error(
          "found none; expected the column of the horizontal component (only `y` may "
          "be none)");
    else
      c.none = true;
  } else if (node->is_scalar() && !node->text().empty() &&
             std::isdigit(static_cast<unsigned char>(node->text()[0]))) {
    if (auto n = node->integer(2, 1000)) c.number = static_cast<int>(*n);
  } else if (format == RecordFormat::Csv) {
    if (auto name = node->string("a column name of the header")) c.name = *name;
  } else {
    node->error("found " + node->found() +
                "; expected a column number >= 2 or none (a columns file has no header)");
  }
  return c;
}

/// Standard gravity, the unit `g` of accelerations (m/s^2).
constexpr double kStandardGravity = 9.80665;

/// The kind of quantity a record of `quantity` holds.
const QuantityKind& kind_of(MotionQuantity quantity) {
  static constexpr const QuantityKind* kKinds[] = {&quantity::acceleration, &quantity::velocity,
                                                   &quantity::length};
  return *kKinds[static_cast<int>(quantity)];
}

/// The unit's SI factor for `quantity` (`g` is standard gravity for
/// accelerations); reported at `node` when it is of another dimension.
std::optional<double> record_unit(const ConfigNode& node, MotionQuantity quantity) {
  const QuantityKind& kind = kind_of(quantity);
  const std::optional<std::string> text = node.string("a unit");
  if (!text) return std::nullopt;
  if (quantity == MotionQuantity::Acceleration && *text == "g") return kStandardGravity;
  try {
    const Unit unit = parse_unit(*text);
    if (unit.dimension == kind.dimension) return unit.factor;
  } catch (const UnitError&) {
  }
  node.error(fmt::format("found {}; expected a unit of {} ({}{})", node.found(), kind.name,
                         kind.examples,
                         quantity == MotionQuantity::Acceleration ? ", g, cm/s^2" : ""));
  return std::nullopt;
}

/// `mechanics.ground_motion` (docs/dda.md section 10): the record, read now
/// so that its problems are the scene's, located in the record file.
void read_ground_motion(const ConfigNode& node, const Scene& scene, GroundMotionControls& g) {
  ConfigMap map(node, ground_motion_table);
  std::optional<std::filesystem::path> file;
  if (auto f = map.required("file", "a ground-motion record (csv, columns or PEER AT2)"))
    file = scene_relative_file(*f, scene.source, "a ground-motion record");
  RecordFormat format = file ? format_of(*file) : RecordFormat::Columns;
  if (auto f = map.optional("format"))
    if (auto name = f->choice(enum_names(kRecordFormatNames)))
      format = value_of(kRecordFormatNames, *name);
  // PEER's velocity and displacement files (.VT2, .DT2) say what they hold.
  MotionQuantity quantity = file ? quantity_of(*file) : MotionQuantity::Acceleration;
  if (auto q = map.optional("quantity"))
    if (auto name = q->choice(enum_names(kMotionQuantityNames)))
      quantity = value_of(kMotionQuantityNames, *name);
  // PEER files are in g, cm/s and cm; other files in the quantity's SI unit
  // unless told.
  std::optional<double> unit = format != RecordFormat::PeerAt2            ? 1.0
                               : quantity == MotionQuantity::Acceleration ? kStandardGravity
                                                                          : 0.01;
  if (auto u = map.optional("unit")) unit = record_unit(*u, quantity);
  double scale = 1;
  map.read("scale", scale, quantity::dimensionless);  // < 0 turns the record's polarity
  if (scale == 0)
    map.optional("scale")->error("found 0; expected a factor other than 0 (< 0 flips the record)");
  const RecordColumn x = read_column(map, "x", format), y = read_column(map, "y", format);
  std::optional<std::filesystem::path> vertical;
  if (auto v = map.optional("vertical_file")) {
    if (format != RecordFormat::PeerAt2)
      v->error_at_key(
          "found vertical_file for a csv or columns record; expected the vertical "
          "component as a column of the same file (`y`)");
    else
      vertical = scene_relative_file(*v, scene.source, "a ground-motion record");
  }
  map.read("start", g.start, quantity::time, Range::non_negative());
  map.read("baseline_correction", g.baseline_correction);
  if (auto b = map.optional("blocks")) {
    g.blocks.emplace();
    if (auto items = b->list("block names", false))  // [] : no block moves (free field only)
      for (const ConfigNode& item : *items) {
        const std::optional<std::string> name = item.string("a block name");
        if (!name) continue;
        const auto block = std::find_if(scene.blocks.begin(), scene.blocks.end(),
                                        [&](const BlockSpec& s) { return s.name == *name; });
        if (block == scene.blocks.end())
          item.error("found " + item.found() +
                     "; expected the name of a fixed block of the scene's `blocks`");
        else if (!block->fixed)
          item.error("found the free block " + item.found() +
                     "; expected a fixed block (`fixed: true`): the ground motion moves it");
        else
          g.blocks->push_back(*name);
      }
  }
  if (!file || !unit) return;

  // The record itself: problems at their line and column in the file.
  try {
    RecordColumns columns = format == RecordFormat::PeerAt2
                                ? read_peer_at2(*file)
                                : read_record_columns(*file, format, x, y);
    if (vertical) {
      const RecordColumns v = read_peer_at2(*vertical);
      if (v.time != columns.time)
        throw RecordFileError({vertical->string(), 4, 1},
                              fmt::format("found NPTS = {} and DT of its own; expected the "
                                          "horizontal record's ({} points)",
                                          v.time.size(), columns.time.size()));
      columns.y = v.x;
    }
    GroundMotionRecord& r = g.record;
    r.quantity = quantity;
    r.time = std::move(columns.time);
    r.source = file->string() + (vertical ? ", " + vertical->string() : "");
    const double factor = *unit * scale;
    const double largest = kind_of(quantity).largest;
    for (std::size_t k = 0; k < r.time.size(); ++k) {
      const Vec2 value(factor * columns.x[k], columns.y.empty() ? 0.0 : factor * columns.y[k]);
      if (value.cwiseAbs().maxCoeff() > largest) {  // once: a unit slip spoils them all
        node.error(
            fmt::format("found {:g} (SI) at t = {:g} s in {}; expected a {} of at most "
                        "{:g} (a unit slip?)",
                        value.cwiseAbs().maxCoeff(), r.time[k], r.source,
                        name_of(kMotionQuantityNames, quantity), largest));
        break;
      }
      r.values.push_back(value);
    }
  } catch (const RecordFileError& e) {
    // At the key that names the file (the scene's diagnostics are of one
    // file), with the record's own file, line and column.
    const SourceLocation& at = e.where();
    map.optional(vertical && at.file == vertical->string() ? "vertical_file" : "file")
        ->error(fmt::format("{}:{}:{}: {}", at.file, at.line, at.column, e.what()));
  } catch (const SceneError& e) {  // unreadable: read_input_file's message
    map.optional("file")->error(e.what());
  }
}

/// `mechanics.viscous_boundaries` (docs/dda.md section 10).
void read_viscous_boundaries(const ConfigNode& node, const SectionContext& context,
                             std::vector<ViscousBoundaryControls>& boundaries) {
  const std::optional<ConfigList> items = node.list("viscous boundaries", false);
  if (!items) return;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, viscous_table);
    ViscousBoundaryControls b;
    b.location = item.location();
    if (auto line = map.required("line", "a line [[x1, y1], [x2, y2]]"))
      if (auto points = line->points(quantity::length, true)) {
        if (points->size() != 2 || ((*points)[1] - (*points)[0]).norm() == 0)
          line->error("found " + line->found() +
                      "; expected two distinct points [[x1, y1], [x2, y2]]");
        else
          b.from = (*points)[0], b.to = (*points)[1];
      }
    if (auto m = map.optional("material"))
      if (auto material = context.materials().resolve(*m)) b.material = *material;
    map.read("free_field", b.free_field);
    boundaries.push_back(b);
  }
}

/// Every contact needs a joint law: the scene's `joints` may not be empty.
void require_joints(SectionContext& context) {
  if (!context.scene().joints.empty()) return;
  ConfigMap& top = context.top();
  if (auto joints = top.optional("joints")) {
    if (joints->is_null() || joints->is_list())  // other values were reported already
      joints->list("joints", true);
  } else {
    top.report_missing("joints", "a non-empty list of joints (physics lists mechanics)");
  }
}

void read_mechanics(const ConfigNode& node, SectionContext& context) {
  MechanicsControls& settings = context.scene().sections.set(dda::kSettings, MechanicsControls{});
  if (context.scene().has_physics("mechanics")) require_joints(context);
  ConfigMap map(node, mechanics_table);
  constexpr std::string_view kMethods[] = {"dda"};
  if (auto m = map.optional("method")) m->choice(kMethods);
  constexpr std::string_view kPlanes[] = {"strain", "stress"};
  if (auto p = map.optional("plane"))
    if (auto plane = p->choice(kPlanes))
      settings.plane = *plane == "strain" ? PlaneMode::Strain : PlaneMode::Stress;
  if (auto dda = map.optional("dda"))
    read_dda(*dda, settings.dda, context.scene().time,
             runs_in_pseudo_time(context.scene().coupling, "mechanics"));
  if (auto g = map.optional("ground_motion"))
    read_ground_motion(*g, context.scene(), settings.ground_motion.emplace());
  if (auto v = map.optional("viscous_boundaries"))
    read_viscous_boundaries(*v, context, settings.viscous_boundaries);
  if (!settings.ground_motion &&
      std::any_of(settings.viscous_boundaries.begin(), settings.viscous_boundaries.end(),
                  [](const ViscousBoundaryControls& b) { return b.free_field; }))
    map.optional("viscous_boundaries")
        ->error(
            "found a free_field boundary without a ground_motion; expected "
            "mechanics.ground_motion, whose (outcrop) velocity enters through it");
}

/// What the mechanics writes in every scene (DdaProcess::writes() returns it).
constexpr std::string_view kProvides[] = {block_fields::geometry, block_fields::kinematics,
                                          block_fields::stress, kContacts.name};

/// What it exchanges in the iterated scheme: the forces on a continuum
/// interface its blocks are tied to (none without one): its tractions.
constexpr ExchangedFieldKind kExchanges[] = {kTieTractions};

}  // namespace

namespace dda {
const SectionReader kMechanicsSection{
    "mechanics",
    "a mechanics section, because physics lists mechanics (all its keys have defaults: "
    "`mechanics: {}` will do)",
    &read_mechanics,
    nullptr,
    kTables,
    {},
    false,
    kProvides,
    kExchanges};
}  // namespace dda

}  // namespace fissure
