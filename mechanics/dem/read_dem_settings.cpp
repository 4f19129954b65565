// The scene's `dem` section (docs/scene-reference.md "dem"): the explicit
// DEM's controls. Every contact needs a joint law with stiffnesses of its
// own (the DEM has no penalty of its own: UDEC's jkn, jks), so each joint
// the DEM uses is checked here too.
#include <numbers>
#include <string>

#include "core/scene/scene_keys.h"
#include "core/scene/time_limits.h"
#include "core/state/rock_mass.h"
#include "mechanics/dem/dem_settings.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/joints/joint_model.h"

namespace fissure::dem {

namespace {

constexpr std::string_view kDem[] = {"rounding",  "margin",          "time_step",   "safety_factor",
                                     "damping",   "cycles_per_step", "solve_ratio", "max_cycles",
                                     "zone_size", "density_scaling"};
constexpr std::string_view kDamping[] = {"local", "rayleigh"};
constexpr std::string_view kRayleigh[] = {"fraction", "frequency", "mass", "stiffness"};
const KeyTable dem_table{"dem", kDem};
const KeyTable damping_table{"dem.damping", kDamping};
const KeyTable rayleigh_table{"dem.damping.rayleigh", kRayleigh};
const KeyTable* const kTables[] = {&dem_table, &damping_table, &rayleigh_table};

/// The Rayleigh coefficients' units: a frequency (Hz, cycles per second)
/// and the mass-proportional coefficient's rate (1/s).
constexpr QuantityKind kFrequency{"frequency", {0, 0, -1, 0, 0}, "Hz", "Hz", 1, 1e12};
constexpr QuantityKind kRate{"rate", {0, 0, -1, 0, 0}, "1/s, Hz", "1/s", 1, 1e12};

/// `rayleigh: {fraction: XI, frequency: F}` (UDEC's `damping xi f`: the
/// fraction of critical damping xi at the centre frequency f, where the
/// ratio xi(omega) = a / (2 omega) + b omega / 2 is least: a = xi omega,
/// b = xi / omega, omega = 2 pi f), or the coefficients themselves,
/// `rayleigh: {mass: A, stiffness: B}`.
void read_rayleigh(const ConfigNode& node, DemControls& dem) {
  ConfigMap map(node, rayleigh_table);
  if (!map.valid()) return;
  const bool udec = map.contains("fraction") || map.contains("frequency");
  const bool coefficients = map.contains("mass") || map.contains("stiffness");
  if (udec && coefficients) {
    node.error(
        "gives both fraction/frequency and mass/stiffness; expected one form: {fraction: XI, "
        "frequency: F} (UDEC's damping xi f) or {mass: A (1/s), stiffness: B (s)}");
    return;
  }
  if (coefficients) {
    map.read("mass", dem.mass_damping, kRate, Range::non_negative());
    map.read("stiffness", dem.stiffness_damping, quantity::time, Range::non_negative());
    return;
  }
  double fraction = 0, frequency = 0;
  map.read_required("fraction", fraction, quantity::dimensionless, Range::open(0, 1));
  map.read_required("frequency", frequency, kFrequency, Range::positive());
  if (!(fraction > 0 && frequency > 0)) return;
  const double omega = 2 * std::numbers::pi * frequency;
  dem.mass_damping = fraction * omega;
  dem.stiffness_damping = fraction / omega;
}

/// `damping: none`, `damping: {local: alpha}` or `damping: {rayleigh: ...}`.
void read_damping(const ConfigNode& node, DemControls& dem) {
  if (node.is_scalar() && node.text() == "none") {
    dem.local_damping = 0;
    return;
  }
  if (!node.is_map()) {
    node.error("found " + node.found() +
               "; expected 'none' or a map {local: ALPHA} or {rayleigh: {fraction: XI, "
               "frequency: F}}");
    return;
  }
  ConfigMap map(node, damping_table);
  if (auto rayleigh = map.optional("rayleigh")) {
    // Rayleigh's damping is for dynamic runs: no local damping beside it.
    if (map.contains("local")) {
      rayleigh->error(
          "beside local damping; expected one of them: local damping for quasi-static runs, "
          "Rayleigh damping for dynamic ones (docs/dem.md section 10)");
      map.optional("local");
      return;
    }
    dem.local_damping = 0;
    read_rayleigh(*rayleigh, dem);
    return;
  }
  map.read("local", dem.local_damping, quantity::dimensionless, Range::closed_open(0, 1));
}

/// A Coulomb joint without stiffnesses of its own has none the DEM can use:
/// reported at the joint's entry.
void require_joint_stiffness(SectionContext& context) {
  const auto joints = context.top().optional("joints");
  if (!joints || !joints->is_list()) return;  // required and reported by core
  const auto items = joints->list("joints", false);
  if (!items) return;
  std::size_t index = 0;
  for (const ConfigNode& item : *items) {
    if (index >= context.scene().joints.size()) break;
    const joints::JointModel model = joints::joint_model(context.scene().joints[index++]);
    const auto* coulomb = std::get_if<joints::CoulombProperties>(&model);
    if (coulomb && !(coulomb->normal_stiffness > 0) && item.is_map())
      item.error(
          "has no normal_stiffness and shear_stiffness; expected both (Pa/m, e.g. "
          "`normal_stiffness: 10 GPa/m`): the DEM's contacts take their stiffness from the "
          "joint (docs/dem.md section 3)");
  }
}

void read_dem(const ConfigNode& node, SectionContext& context) {
  DemControls& dem = context.scene().sections.set(kDemSettings, DemControls{});
  if (context.scene().has_physics("dem")) {
    if (!context.top().contains("joints"))
      context.top().report_missing("joints", "a non-empty list of joints (physics lists dem)");
    require_joint_stiffness(context);
  }
  ConfigMap map(node, dem_table);
  if (auto r = map.optional("rounding"))
    if (auto d = r->quantity(quantity::length, Range::positive())) {
      dem.rounding = *d;
      dem.rounding_location = r->location();
    }
  if (auto m = map.optional("margin"))
    if (auto d = m->quantity(quantity::length, Range::positive())) dem.margin = *d;
  if (auto step = map.optional("time_step")) {
    if (step->is_scalar() && step->text() == "auto") {
      dem.time_step.reset();
    } else if (auto dt = step->quantity(quantity::time, Range::positive())) {
      dem.time_step = *dt;
      dem.time_step_location = step->location();
      if (!runs_in_pseudo_time(context.scene().coupling, "dem"))
        check_time_step(*step, *dt, context.scene().time);
    }
  }
  map.read("safety_factor", dem.safety_factor, quantity::dimensionless, Range::open_closed(0, 1));
  if (auto d = map.optional("damping")) read_damping(*d, dem);
  map.read("cycles_per_step", dem.cycles_per_step, 1);
  if (auto r = map.optional("solve_ratio"))
    if (auto ratio = r->quantity(quantity::dimensionless, Range::open(0, 1)))
      dem.solve_ratio = *ratio;
  map.read("max_cycles", dem.max_cycles, 1);
  if (auto z = map.optional("zone_size"))
    if (auto size = z->quantity(quantity::length, Range::positive())) dem.zone_size = *size;
  if (auto d = map.optional("density_scaling")) {
    if (auto on = d->boolean()) dem.density_scaling = *on;
    // The scaled masses change the motion: only a solve to a ratio, in
    // pseudo-time, may use them, and the step is then the scaled one.
    if (dem.density_scaling && !dem.solve_ratio)
      d->error(
          "is true without dem.solve_ratio; expected density scaling only in the "
          "quasi-static mode (set solve_ratio, e.g. 1e-5): it changes the blocks' motion "
          "(docs/dem.md section 2)");
    else if (dem.density_scaling && dem.time_step)
      d->error(
          "is true with a dem.time_step given; expected `time_step: auto` (density "
          "scaling sets the step from the blocks' largest natural one)");
  }
}

/// What the DEM writes in every scene (DemProcess::writes() returns it): the
/// same fields as any block process, so that the flow's HM coupling and the
/// heat's closed joints work with it unchanged.
constexpr std::string_view kProvides[] = {block_fields::geometry, block_fields::kinematics,
                                          block_fields::stress, kContacts.name};

}  // namespace

const SectionReader kDemSection{
    "dem",
    "a dem section, because physics lists dem (all its keys have defaults: `dem: {}` will do)",
    &read_dem,
    nullptr,
    kTables,
    {},
    false,
    kProvides};

}  // namespace fissure::dem
