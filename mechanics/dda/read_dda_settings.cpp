// The scene's `mechanics` section: method, plane mode and Shi's DDA controls
// (theory.md 1.7, 7.1). Every contact needs a joint law, so the DDA also
// needs the scene's joints.
#include <cctype>

#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_keys.h"
#include "core/scene/time_limits.h"
#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_settings.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/interface_ties.h"

namespace fissure {

namespace {

constexpr std::string_view kMechanics[] = {"method", "plane", "dda"};
constexpr std::string_view kDda[] = {
    "time_step",      "max_displacement_ratio",    "penalty",
    "penalty_factor", "shear_penalty_ratio",       "velocity_carry_over",
    "damping_ratio",  "max_open_close_iterations", "exact_rotation",
    "solver"};
const KeyTable mechanics_table{"mechanics", kMechanics};
const KeyTable dda_table{"mechanics.dda", kDda};
const KeyTable solver_table{"mechanics.dda.solver", scene_keys::linear_solver};
const KeyTable* const kTables[] = {&mechanics_table, &dda_table, &solver_table};

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
  if (auto s = map.optional("solver")) read_linear_solver(*s, solver_table, dda.solver);
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
