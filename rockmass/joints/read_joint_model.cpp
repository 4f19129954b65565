#include "rockmass/joints/read_joint_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <span>
#include <string>

#include "rockmass/joints/joint_model.h"
#include "rockmass/physical_quantities.h"

namespace fissure::joints {

namespace {

/// A key of an entry and the models it belongs to (core's name and
/// friction angle belong to all).
struct Owner {
  std::string_view key;
  bool coulomb, barton_bandis, continuously_yielding;
};
/// The keys this reader reads besides `model`, then the two Coulomb keys
/// core reads (kCoreKeys).
constexpr Owner kOwners[] = {{"normal_stiffness", true, false, true},
                             {"shear_stiffness", true, false, true},
                             {"dilation_angle", true, false, false},
                             {"zero_dilation_displacement", true, false, false},
                             {"jrc", false, true, false},
                             {"jcs", false, true, false},
                             {"lab_length", false, true, false},
                             {"field_length", false, true, false},
                             {"initial_aperture", false, true, false},
                             {"initial_normal_stiffness", false, true, false},
                             {"max_closure", false, true, false},
                             {"initial_friction_angle", false, false, true},
                             {"roughness_length", false, false, true},
                             {"normal_stiffness_exponent", false, false, true},
                             {"shear_stiffness_exponent", false, false, true},
                             {"reference_normal_stress", false, false, true},
                             {"cohesion", true, false, false},
                             {"tensile_strength", true, false, false}};
constexpr std::size_t kCoreKeys = 2;

/// The reader's key table: `model` and the keys of kOwners but core's.
constexpr auto kKeys = [] {
  std::array<std::string_view, 1 + std::size(kOwners) - kCoreKeys> keys{};
  keys[0] = "model";
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) keys[k + 1] = kOwners[k].key;
  return keys;
}();

constexpr bool owns(const Owner& o, JointModelKind kind) {
  switch (kind) {
    case JointModelKind::Coulomb:
      return o.coulomb;
    case JointModelKind::BartonBandis:
      return o.barton_bandis;
    case JointModelKind::ContinuouslyYielding:
      return o.continuously_yielding;
  }
  return false;
}

/// The keys of an entry of model `kind`, for the unknown-key message:
/// core's name and friction angle (and Coulomb's cohesion and tensile
/// strength), `model`, then the model's own.
template <JointModelKind kind>
constexpr auto keys_of() {
  constexpr std::size_t n = 3 + std::count_if(std::begin(kOwners), std::end(kOwners),
                                              [](const Owner& o) { return owns(o, kind); });
  std::array<std::string_view, n> keys{};
  std::size_t i = 0;
  keys[i++] = "name";
  keys[i++] = "friction_angle";
  for (std::size_t k = std::size(kOwners) - kCoreKeys; k < std::size(kOwners); ++k)
    if (owns(kOwners[k], kind)) keys[i++] = kOwners[k].key;
  keys[i++] = "model";
  for (std::size_t k = 0; k + kCoreKeys < std::size(kOwners); ++k)
    if (owns(kOwners[k], kind)) keys[i++] = kOwners[k].key;
  return keys;
}
constexpr auto kCoulombKeys = keys_of<JointModelKind::Coulomb>();
constexpr auto kBartonBandisKeys = keys_of<JointModelKind::BartonBandis>();
constexpr auto kContinuouslyYieldingKeys = keys_of<JointModelKind::ContinuouslyYielding>();

std::span<const std::string_view> keys_of(JointModelKind kind) {
  switch (kind) {
    case JointModelKind::Coulomb:
      return kCoulombKeys;
    case JointModelKind::BartonBandis:
      return kBartonBandisKeys;
    case JointModelKind::ContinuouslyYielding:
      return kContinuouslyYieldingKeys;
  }
  return {};
}

/// The names of the models a key belongs to: "model coulomb or continuously_yielding".
std::string owners_of(const Owner& o) {
  std::string names;
  for (const auto& row : kJointModelNames)
    if (owns(o, row.value)) names += (names.empty() ? "model " : " or ") + std::string(row.name);
  return names;
}

/// A key of another model is an error at the key (core has read cohesion
/// and tensile strength already: reading them again only finds their nodes).
void refuse_other_models_keys(ConfigMap& map, JointModelKind kind) {
  const std::string_view name = name_of(kJointModelNames, kind);
  for (const Owner& o : kOwners)
    if (!owns(o, kind) && map.contains(o.key))
      map.optional(o.key)->error_at_key(
          fmt::format("found '{}', a key of {}; expected it removed, or that model for this "
                      "joint (its model is {})",
                      o.key, owners_of(o), name));
}

const Range kAcute = Range::closed_open(0, 90 * quantity::kDegree);
/// Barton and Choubey's limit on the friction angle (docs/joints.md 3).
constexpr double kBartonMaxAngle = 70 * quantity::kDegree;

void read_coulomb(ConfigMap& map, JointProperties& joint, bool named) {
  CoulombProperties c;
  c.friction_angle = joint.friction_angle;
  c.cohesion = joint.cohesion;
  c.tensile_strength = joint.tensile_strength;
  const bool has_kn = map.contains("normal_stiffness"), has_ks = map.contains("shear_stiffness");
  map.read("normal_stiffness", c.normal_stiffness, quantity::joint_normal_stiffness,
           Range::positive());
  map.read("shear_stiffness", c.shear_stiffness, quantity::joint_shear_stiffness,
           Range::positive());
  if (has_kn != has_ks)
    map.report_missing(has_kn ? "shear_stiffness" : "normal_stiffness",
                       "both normal_stiffness and shear_stiffness, or neither (the process's "
                       "own contact springs)");
  const bool dilates = map.contains("dilation_angle") || map.contains("zero_dilation_displacement");
  map.read("dilation_angle", c.dilation_angle, quantity::angle, kAcute);
  map.read("zero_dilation_displacement", c.zero_dilation_displacement, quantity::length,
           Range::non_negative());
  // Coulomb with the keys core read alone stays as it was (no model value):
  // the DDA's joints of every existing scene.
  if (named || has_kn || has_ks || dilates) joint.model.set(kJointModel, JointModel{c});
}

void read_barton_bandis(ConfigMap& map, JointProperties& joint) {
  BartonBandisProperties b;
  b.residual_friction_angle = joint.friction_angle;
  if (joint.friction_angle >= kBartonMaxAngle)
    if (auto node = map.optional("friction_angle"))
      node->error(
          fmt::format("found {}; expected a residual friction angle phi_r below 70 deg (Barton and "
                      "Choubey's limit on phi_r + JRC log10(JCS/sigma_n))",
                      node->found()));
  map.read_required("jrc", b.jrc, quantity::dimensionless, Range::open_closed(0, 20));
  map.read_required("jcs", b.jcs, quantity::stress, Range::positive());
  map.read_required("lab_length", b.lab_length, quantity::length, Range::positive());
  map.read("field_length", b.field_length, quantity::length, Range::positive());
  map.read_required("initial_aperture", b.initial_aperture, quantity::length, Range::positive());
  map.read("initial_normal_stiffness", b.initial_normal_stiffness, quantity::joint_normal_stiffness,
           Range::positive());
  map.read("max_closure", b.max_closure, quantity::length, Range::positive());
  if (!(b.jrc > 0 && b.jcs > 0 && b.lab_length > 0 && b.initial_aperture > 0)) return;  // reported

  // k_ni and V_m not given come from Bandis's regressions, which hold
  // for the data's range only.
  if (b.max_closure >= b.initial_aperture) {
    map.optional("max_closure")
        ->error(fmt::format("found {:.4g} mm, not below initial_aperture ({:.4g} mm); expected "
                            "a closure smaller than the aperture",
                            b.max_closure * 1e3, b.initial_aperture * 1e3));
    return;
  }
  const BandisClosure r = bandis_regression(b.jrc, b.jcs, b.initial_aperture);
  const bool bad_kni = b.initial_normal_stiffness == 0 && !(r.initial_normal_stiffness > 0);
  const bool bad_vm =
      b.max_closure == 0 && !(r.max_closure > 0 && r.max_closure < b.initial_aperture);
  if (bad_kni || bad_vm)
    map.node().error(fmt::format(
        "found JRC {:.4g}, JCS {:.4g} MPa and initial_aperture {:.4g} mm, for which Bandis's "
        "regressions give {}; expected {} given",
        b.jrc, b.jcs / 1e6, b.initial_aperture * 1e3,
        bad_kni
            ? fmt::format("k_ni = {:.4g} GPa/m", r.initial_normal_stiffness / 1e9)
            : fmt::format("V_m = {:.4g} mm (not in (0, initial_aperture))", r.max_closure * 1e3),
        bad_kni ? "initial_normal_stiffness" : "max_closure"));
  // JCS at the field length where it is known (JCS_0 bounds JCS_n from
  // above for field lengths beyond the lab's).
  joint.largest_normal_stress =
      b.field_length > 0 ? scaled_jcs(b.jcs, b.jrc, b.lab_length, b.field_length) : b.jcs;
  joint.largest_normal_stress_key = "jcs";
  joint.model.set(kJointModel, JointModel{b});
}

void read_continuously_yielding(ConfigMap& map, JointProperties& joint) {
  ContinuouslyYieldingProperties y;
  y.friction_angle = joint.friction_angle;
  map.read_required("normal_stiffness", y.normal_stiffness, quantity::joint_normal_stiffness,
                    Range::positive());
  map.read_required("shear_stiffness", y.shear_stiffness, quantity::joint_shear_stiffness,
                    Range::positive());
  map.read("normal_stiffness_exponent", y.normal_stiffness_exponent, quantity::dimensionless,
           Range::closed_open(0, 1));
  map.read("shear_stiffness_exponent", y.shear_stiffness_exponent, quantity::dimensionless,
           Range::closed_open(0, 1));
  map.read("reference_normal_stress", y.reference_normal_stress, quantity::stress,
           Range::positive());
  map.read_required("initial_friction_angle", y.initial_friction_angle, quantity::angle,
                    Range::closed_open(joint.friction_angle, 90 * quantity::kDegree));
  map.read_required("roughness_length", y.roughness_length, quantity::length, Range::positive());
  joint.model.set(kJointModel, JointModel{y});
}

void read_joint_model(ConfigMap& map, JointProperties& joint) {
  JointModelKind kind = JointModelKind::Coulomb;
  bool named = false;
  if (auto node = map.optional("model")) {
    const auto name = node->choice(enum_names(kJointModelNames));
    if (!name) {  // reported; the model's keys would only add noise
      for (std::string_view key : kKeys) map.optional(key);
      return;
    }
    kind = value_of(kJointModelNames, *name);
    named = true;
  }
  map.list_keys(keys_of(kind));
  refuse_other_models_keys(map, kind);
  switch (kind) {
    case JointModelKind::Coulomb:
      read_coulomb(map, joint, named);
      break;
    case JointModelKind::BartonBandis:
      read_barton_bandis(map, joint);
      break;
    case JointModelKind::ContinuouslyYielding:
      read_continuously_yielding(map, joint);
      break;
  }
}

}  // namespace

const KeyTable kJointModelKeys{"joints[]", kKeys};
const JointModelReader kJointModelReader{&kJointModelKeys, &read_joint_model};

}  // namespace fissure::joints
