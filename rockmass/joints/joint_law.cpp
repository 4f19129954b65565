#include "rockmass/joints/joint_law.h"

#include <cmath>

namespace fissure::joints {

namespace {

std::variant<CoulombSlip, BartonBandis, ContinuouslyYielding> make_law(const JointModel& model) {
  return std::visit(
      [](const auto& p) -> std::variant<CoulombSlip, BartonBandis, ContinuouslyYielding> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, CoulombProperties>) return CoulombSlip(p);
        if constexpr (std::is_same_v<P, BartonBandisProperties>) return BartonBandis(p);
        if constexpr (std::is_same_v<P, ContinuouslyYieldingProperties>)
          return ContinuouslyYielding(p);
      },
      model);
}

}  // namespace

JointLaw::JointLaw(const JointModel& model) : law_(make_law(model)) {}

JointLaw::State JointLaw::state_at(double gap, bool bonded) const {
  return std::visit(
      [&](const auto& law) -> State {
        auto s = law.initial_state();
        s.normal_displacement = gap;
        if constexpr (std::is_same_v<decltype(s), CoulombSlip::State>) s.intact = bonded;
        return s;
      },
      law_);
}

JointLaw::State JointLaw::prestressed_state(double gap, double normal_stress, double shear_stress,
                                            double length) const {
  if (!(normal_stress > 0)) return state_at(gap, true);
  return std::visit(
      [&](const auto& law) -> State {
        using Law = std::decay_t<decltype(law)>;
        auto s = law.initial_state();
        double closure = 0;
        if constexpr (std::is_same_v<Law, CoulombSlip>) {
          closure = normal_stress / law.properties().normal_stiffness;
          s.shear_displacement = shear_stress / law.properties().shear_stiffness;
        } else if constexpr (std::is_same_v<Law, BartonBandis>) {
          closure = law.loaded(normal_stress, 0, law.field_length(length)).closure;
          // Its strength mobilized as far as the stress it carries needs.
          s.mobilized_displacement =
              law.mobilized_displacement_for(normal_stress, shear_stress, length);
        } else {
          closure = law.closure(normal_stress);
        }
        s.normal_displacement = gap - closure;
        s.normal_stress = normal_stress;
        s.shear_stress = shear_stress;
        return s;
      },
      law_);
}

JointResponse JointLaw::update(const State& before, const JointIncrement& step,
                               State& after) const {
  return std::visit(
      [&](const auto& law) {
        using S = typename std::decay_t<decltype(law)>::State;
        FISSURE_CHECK(std::holds_alternative<S>(before), std::logic_error,
                      "a joint state of another law");
        if (!std::holds_alternative<S>(after)) after.template emplace<S>();
        return law.update(std::get<S>(before), step, std::get<S>(after));
      },
      law_);
}

JointStiffness JointLaw::stiffness(double normal_stress, double length) const {
  const double sigma = std::max(0.0, normal_stress);
  if (const auto* c = std::get_if<CoulombSlip>(&law_))
    return {c->properties().normal_stiffness, c->properties().shear_stiffness};
  if (const auto* b = std::get_if<BartonBandis>(&law_))
    return {b->normal_stiffness_at(sigma, length), b->shear_stiffness_at(sigma, length)};
  const auto& y = std::get<ContinuouslyYielding>(law_);
  return {y.normal_stiffness(sigma), y.shear_stiffness(sigma)};
}

double JointLaw::friction_coefficient(const State& state, double normal_stress,
                                      double length) const {
  return std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        const auto* s = std::get_if<typename Law::State>(&state);
        FISSURE_CHECK(s, std::logic_error, "a joint state of another law");
        if constexpr (std::is_same_v<Law, CoulombSlip>)
          return std::tan(law.properties().friction_angle);
        else if constexpr (std::is_same_v<Law, BartonBandis>)
          return std::tan(law.friction_angle_at(*s, normal_stress, length));
        else
          return std::tan(s->bounding_friction_angle);
      },
      law_);
}

}  // namespace fissure::joints
