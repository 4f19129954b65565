// One joint law of any kind behind one interface (docs/joints.md section 6):
// what a process holds per scene joint, with the per-contact State of that
// law, so that a process whose contacts meet joints of several models (a
// Coulomb bedding plane and a Barton-Bandis cross joint) steps each with its
// own law without knowing which. Each call dispatches once on the law's kind
// (std::visit over three alternatives): no virtual call, no allocation.
#pragma once

#include <concepts>
#include <utility>
#include <variant>
#include <vector>

#include "core/base/errors.h"
#include "rockmass/joints/joint_model.h"

namespace fissure::joints {

/// The stiffnesses of a joint at a normal stress (Pa/m): what an explicit
/// method's critical time step needs.
struct JointStiffness {
  double normal = 0;
  double shear = 0;
};

class JointLaw {
 public:
  /// One contact's state, of its law's kind.
  using State = std::variant<CoulombSlip::State, BartonBandis::State, ContinuouslyYielding::State>;

  /// Throws std::invalid_argument for properties out of range.
  explicit JointLaw(const JointModel& model);

  JointModelKind kind() const { return static_cast<JointModelKind>(law_.index()); }

  /// A contact found with its walls `gap` apart (m, < 0 overlapping),
  /// without stress. `bonded`: the walls were closed at the start of the run
  /// (a joint of the intact rock mass), so a Coulomb joint keeps its
  /// cohesion and tensile strength until it first fails; a contact made
  /// later has none.
  State state_at(double gap, bool bonded) const;

  /// A bonded contact found at `gap` that already carries the normal
  /// stress sigma_n (Pa, compression +) and the shear stress tau of the
  /// rock mass's initial stress: its walls closed by the law's closure at
  /// sigma_n (beyond the gap) and the stresses in its state. sigma_n <= 0:
  /// state_at(gap, true).
  State prestressed_state(double gap, double normal_stress, double shear_stress,
                          double length) const;

  /// One step (joint_step.h): `before` and `after` of this law's kind.
  JointResponse update(const State& before, const JointIncrement& step, State& after) const;

  /// The tangent stiffnesses at the normal stress sigma_n (Pa, compression
  /// +): Coulomb's constants, Bandis's hyperbola (and Barton's peak shear
  /// stiffness at the length `length`), the continuously yielding law's
  /// power laws.
  JointStiffness stiffness(double normal_stress, double length) const;

  /// The shear strength over sigma_n of a contact in `state` at the normal
  /// stress sigma_n (Pa, compression +), for a method that carries the
  /// contact's forces with its own springs and takes only the strength from
  /// the law (the DDA, docs/dda.md section 9): Coulomb's tan(phi) (its
  /// cohesion and tension are the method's), Barton-Bandis's tan(phi_mob) at
  /// sigma_n and the state's mobilized displacement, the continuously
  /// yielding law's tan(phi_m). `length`: the contact's length (m), the
  /// Barton-Bandis field length where neither the properties nor the state
  /// fix one.
  double friction_coefficient(const State& state, double normal_stress, double length) const;

 private:
  std::variant<CoulombSlip, BartonBandis, ContinuouslyYielding> law_;
};

namespace detail {
inline constexpr const char* kStateListNames[] = {"coulomb_states", "barton_bandis_states",
                                                  "continuously_yielding_states"};
}

/// Writes or reads (core/io/checkpoint.h) the states of a process's
/// contacts, in their order: the kind of each, then one list per kind (the
/// columns of one list have the same fields in every row).
template <class Archive, class States>
requires std::same_as<std::remove_const_t<States>, std::vector<JointLaw::State>>
void checkpoint_law_states(Archive& a, States& states) {
  std::vector<int> kinds;
  if constexpr (!Archive::reading)
    for (const JointLaw::State& s : states) kinds.push_back(static_cast<int>(s.index()));
  a("law_kinds", kinds);
  if constexpr (Archive::reading) {
    for (int k : kinds)
      FISSURE_CHECK(k >= 0 && k < static_cast<int>(std::variant_size_v<JointLaw::State>), IoError,
                    "checkpoint: law_kinds holds " << k << ", not a joint law");
    states.resize(kinds.size());
  }
  auto one_kind = [&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    using T = std::variant_alternative_t<I, JointLaw::State>;
    std::vector<T> of_kind;
    if constexpr (!Archive::reading)
      for (const JointLaw::State& s : states)
        if (s.index() == I) of_kind.push_back(std::get<I>(s));
    a.list(detail::kStateListNames[I], of_kind, [](auto& e, auto& s) { checkpoint_fields(e, s); });
    if constexpr (Archive::reading) {
      std::size_t next = 0;
      for (std::size_t k = 0; k < kinds.size(); ++k) {
        if (kinds[k] != static_cast<int>(I)) continue;
        FISSURE_CHECK(next < of_kind.size(), IoError,
                      "checkpoint: fewer " << detail::kStateListNames[I] << " than law_kinds says");
        states[k].template emplace<I>(of_kind[next++]);
      }
      FISSURE_CHECK(next == of_kind.size(), IoError,
                    "checkpoint: more " << detail::kStateListNames[I] << " than law_kinds says");
    }
  };
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (one_kind(std::integral_constant<std::size_t, I>{}), ...);
  }
  (std::make_index_sequence<std::variant_size_v<JointLaw::State>>{});
}

}  // namespace fissure::joints
