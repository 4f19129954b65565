// The iterated scheme's convergence test, field by field (coupling/
// field_convergence.h, docs/architecture.md 5): a coupled step whose
// exchanged values pair a pressure of 1 MPa that is right from the first pass
// with a width of 0.1 mm that the fixed point halves the error of in each
// pass. The pooled relative norm of the values together accepts the first
// pass, the width 25 % off; per field the step iterates until the width is
// within its own tolerance. And the tolerances a scene gives per field.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "core/process/exchanged_values.h"
#include "core/process/process.h"
#include "coupling/field_convergence.h"
#include "coupling/process_registry.h"
#include "coupling/splitting.h"
#include "tests/support/bad_scene_checks.h"

using namespace fissure;

namespace {

constexpr Key<std::vector<double>> kSeenWidth{"test.seen_width"};
constexpr Key<std::vector<double>> kPressure{"test.pressure"};
constexpr Key<std::vector<double>> kWidth{"test.width"};

constexpr ExchangedFieldKind kFields[] = {{"test.pressure", &quantity::stress},
                                          {"test.width", &quantity::length}};

constexpr double kPressureValue = 1e6;     // Pa
constexpr double kWidthFixedPoint = 1e-4;  // m
constexpr double kStartWidth = 2e-4;       // m

/// Reads the width the second process left and passes it on (as the
/// mechanics passes the flow's pressures on to the block faces).
class Reader final : public Process {
 public:
  std::string name() const override { return "reader"; }
  std::vector<std::string> reads() const override { return {"test.width"}; }
  std::vector<std::string> writes() const override { return {"test.seen_width"}; }
  void initialize(RockMass&) override {}
  double proposed_dt(const RockMass&) const override { return 1; }
  StepReport advance(RockMass& state, double, double) override {
    state.fields.set(kSeenWidth, state.fields.get(kWidth));
    return {};
  }
  nlohmann::json statistics() const override { return nlohmann::json::object(); }
  nlohmann::json energy(const RockMass&) const override { return nlohmann::json::object(); }
  void save(CheckpointWriter&, const RockMass&) const override {}
  void restore(CheckpointReader&, RockMass&) override {}
};

/// The fixed point w = g(w) = w* + (w - w*) / 2 of the width it is given,
/// and a pressure that does not depend on it.
class Halver final : public Process {
 public:
  std::string name() const override { return "halver"; }
  std::vector<std::string> reads() const override { return {"test.seen_width"}; }
  std::vector<std::string> writes() const override { return {"test.pressure", "test.width"}; }
  void initialize(RockMass&) override {}
  double proposed_dt(const RockMass&) const override { return 1; }
  StepReport advance(RockMass& state, double, double) override {
    const double seen = state.fields.get(kSeenWidth)[0];
    state.fields.set(kWidth,
                     std::vector<double>{kWidthFixedPoint + 0.5 * (seen - kWidthFixedPoint)});
    state.fields.set(kPressure, std::vector<double>{kPressureValue});
    return {};
  }
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override {
    return gather_exchanged(state, kFields, [](auto& s, auto&& visit) { for_each(s, visit); });
  }
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override {
    scatter_exchanged(state, values, [](auto& s, auto&& visit) { for_each(s, visit); });
  }
  nlohmann::json statistics() const override { return nlohmann::json::object(); }
  nlohmann::json energy(const RockMass&) const override { return nlohmann::json::object(); }
  void save(CheckpointWriter&, const RockMass&) const override {}
  void restore(CheckpointReader&, RockMass&) override {}

 private:
  template <class Visit>
  static void for_each(auto& state, Visit&& visit) {
    for (auto& v : state.fields.get(kPressure)) visit(0, v);
    for (auto& v : state.fields.get(kWidth)) visit(1, v);
  }
};

RockMass start_state() {
  RockMass state;
  state.fields.set(kWidth, std::vector<double>{kStartWidth});
  state.fields.set(kSeenWidth, std::vector<double>{kStartWidth});
  state.fields.set(kPressure, std::vector<double>{kPressureValue});
  return state;
}

CouplingSettings iterated(double tolerance) {
  CouplingSettings c;
  c.scheme = CouplingSettings::Scheme::Iterated;
  c.iteration.tolerance = tolerance;
  c.iteration.max_iterations = 100;
  c.iteration.relaxation = CouplingSettings::Iteration::Relaxation::Fixed;
  c.iteration.omega = 1;
  return c;
}

}  // namespace

TEST(FieldConvergence, ASmallFieldIsIteratedToItsOwnToleranceBesideALargeOne) {
  // The first pass: the width goes from 2e-4 to 1.5e-4 m, the pressure
  // stays. The pooled relative Euclidean norm of (pressure, width) would
  // accept it: a 25 % change of the width is 5e-11 of the pressure.
  const double change = 0.5e-4, pooled = std::hypot(kPressureValue, 1.5e-4);
  ASSERT_LE(change, 1e-6 * pooled) << "the case no longer shows what the pooled norm accepts";

  Reader reader;
  Halver halver;
  const CouplingSettings coupling = iterated(1e-6);
  Splitting splitting({&reader, &halver}, coupling, 10, 1e-9);
  RockMass state = start_state();
  splitting.start(state);
  splitting.step(state, 1);
  // Per field: the width's error halves each pass, from 1e-4 m, until a
  // pass changes it by at most 1e-6 of itself (1e-10 m): 21 passes.
  const double width = state.fields.get(kWidth)[0];
  EXPECT_LE(std::abs(width - kWidthFixedPoint), 2e-6 * kWidthFixedPoint);
  const nlohmann::json s = splitting.statistics()["iteration"];
  EXPECT_EQ(s["not_converged_steps"], 0);
  const long passes = s["passes"];
  const long expected = 1 + static_cast<long>(std::ceil(std::log2(change / (1e-6 * 1e-4))));
  EXPECT_NEAR(passes, expected, 1);
  // Which field kept the step iterating, and how far each last moved.
  EXPECT_EQ(s["fields"]["test.width"]["passes_over_tolerance"], passes - 1);
  EXPECT_EQ(s["fields"]["test.pressure"]["passes_over_tolerance"], 0);
  EXPECT_EQ(s["fields"]["test.width"]["unit"], "m");
  EXPECT_LE(s["fields"]["test.width"]["last_change"].get<double>(), 1e-6 * 1e-4);
  EXPECT_GT(s["fields"]["test.width"]["last_change"].get<double>(), 0);
}

TEST(FieldConvergence, AFieldsOwnToleranceOverridesTheSchemes) {
  // A relative tolerance of 1e-2 for the width alone: the step stops when a
  // pass changes it by less than 1 % (7 passes), however tight the rest.
  CouplingSettings coupling = iterated(1e-9);
  coupling.iteration.fields["test.width"].relative = 1e-2;
  Reader reader;
  Halver halver;
  Splitting splitting({&reader, &halver}, coupling, 10, 1e-9);
  RockMass state = start_state();
  splitting.start(state);
  splitting.step(state, 1);
  const nlohmann::json s = splitting.statistics()["iteration"];
  const double last = s["fields"]["test.width"]["last_change"];
  EXPECT_LE(last, 1e-2 * state.fields.get(kWidth)[0]);
  EXPECT_GT(2 * last, 1e-2 * state.fields.get(kWidth)[0]);  // the pass before was over it
  EXPECT_EQ(s["fields"]["test.width"]["relative_tolerance"], 1e-2);
  EXPECT_EQ(s["fields"]["test.pressure"]["relative_tolerance"], 1e-9);
  // An absolute tolerance ends it as soon as the change is below it.
  coupling.iteration.fields["test.width"] = {std::nullopt, 1e-5};
  Splitting loose({&reader, &halver}, coupling, 10, 1e-9);
  RockMass other = start_state();
  loose.start(other);
  loose.step(other, 1);
  // Changes 5e-5, 2.5e-5, 1.25e-5, 6.25e-6: the fourth pass is within 1e-5 m.
  EXPECT_EQ(loose.statistics()["iteration"]["passes"], 4);
}

TEST(FieldConvergence, AitkensFactorIsTheSameInAnyUnit) {
  // Aitken on the normalized residuals: a width given in m or, scaled by
  // 1e6 with a tolerance scaled alike, in um, iterates alike.
  FieldConvergence convergence(CouplingSettings{}.iteration);
  const ExchangedFieldKind width{"w", &quantity::length};
  EXPECT_EQ(convergence.tolerance(width, 0), 1e-12);
  EXPECT_EQ(convergence.tolerance(width, 1e-4), 1e-10);
  const ExchangedFieldKind pressure{"p", &quantity::stress};
  EXPECT_EQ(convergence.tolerance(pressure, 0), 1e-3);
  Relaxation in_m(CouplingSettings{}.iteration), in_um(CouplingSettings{}.iteration);
  std::vector<double> x_m{1e-4}, x_um{100};
  in_m.relax(x_m, std::vector<double>{1e-5}, std::vector<double>{1e-10});
  in_um.relax(x_um, std::vector<double>{10}, std::vector<double>{1e-4});
  in_m.relax(x_m, std::vector<double>{-4e-6}, std::vector<double>{1e-10});
  in_um.relax(x_um, std::vector<double>{-4}, std::vector<double>{1e-4});
  EXPECT_DOUBLE_EQ(in_m.omega(), in_um.omega());
  EXPECT_DOUBLE_EQ(x_m[0] * 1e6, x_um[0]);
}

// Quasi-Newton (IQN-ILS) on a linear pass x~ = A x + b whose modes contract
// at 0.99, 0.9, 0.5, -0.5 and -0.95 (a tied block region's traction modes
// are of this kind): it learns A's action from the passes and reaches the
// fixed point to 1e-12 in 7 passes, as GMRES would in n + 1; Aitken's one
// factor, capped at 1, needs hundreds.
TEST(FieldConvergence, QuasiNewtonSolvesALinearPassOfManyModes) {
  const Eigen::Vector<double, 5> mu(0.99, 0.9, 0.5, -0.5, -0.95);
  // A = Q diag(mu) Q^T with a fixed rotation Q, b such that x* = (1, ..., 5).
  Eigen::Matrix<double, 5, 5> q = Eigen::Matrix<double, 5, 5>::Identity();
  for (int k = 0; k < 4; ++k) {
    const double c = std::cos(0.3 + k), s = std::sin(0.3 + k);
    Eigen::Matrix<double, 5, 5> g = Eigen::Matrix<double, 5, 5>::Identity();
    g(k, k) = c, g(k + 1, k + 1) = c, g(k, k + 1) = -s, g(k + 1, k) = s;
    q = q * g;
  }
  const Eigen::Matrix<double, 5, 5> a = q * mu.asDiagonal() * q.transpose();
  const Eigen::Vector<double, 5> fixed(1, 2, 3, 4, 5);
  const Eigen::Vector<double, 5> b = fixed - a * fixed;
  auto passes_to = [&](CouplingSettings::Iteration::Relaxation kind, double tolerance) {
    CouplingSettings::Iteration controls;
    controls.relaxation = kind;
    Relaxation relaxation(controls);
    std::vector<double> x(5, 0.0), scale(5, 1.0);
    for (int pass = 1; pass <= 2000; ++pass) {
      const Eigen::Vector<double, 5> xv = Eigen::Map<Eigen::Vector<double, 5>>(x.data());
      const Eigen::Vector<double, 5> r = a * xv + b - xv;
      if (r.norm() < tolerance) return pass;
      relaxation.relax(x, std::vector<double>(r.data(), r.data() + 5), scale);
    }
    return 2001;
  };
  const int quasi_newton = passes_to(CouplingSettings::Iteration::Relaxation::QuasiNewton, 1e-12);
  const int aitken = passes_to(CouplingSettings::Iteration::Relaxation::Aitken, 1e-12);
  std::printf("passes to 1e-12: quasi-Newton %d, Aitken %d\n", quasi_newton, aitken);
  EXPECT_LE(quasi_newton, 8);
  EXPECT_GT(aitken, 100);
}

TEST(FieldConvergence, TheScenesFieldTolerancesAreReadInTheFieldsUnit) {
  const std::string scene =
      fissure::testing::replace(fissure::testing::kValid, "physics: [mechanics]",
                                "physics: [mechanics, flow]") +
      "flow: {hm: {normal_stiffness: 10 GPa/m}}\n";
  auto with = [&scene](const std::string& iteration) {
    return scene + "coupling:\n  scheme: iterated\n  iteration: " + iteration + "\n";
  };
  const Scene s = read_scene_text(
      with("{fields: {pressure_loads: {absolute: 1 kPa}, fracture_flow.aperture: {relative: "
           "1e-4, absolute: 1e-9 m}}}"),
      "ok.yaml");
  const auto& f = s.coupling.iteration.fields;
  EXPECT_EQ(f.at("pressure_loads").absolute, 1e3);
  EXPECT_FALSE(f.at("pressure_loads").relative);
  EXPECT_EQ(f.at("fracture_flow.aperture").relative, 1e-4);
  EXPECT_DOUBLE_EQ(*f.at("fracture_flow.aperture").absolute, 1e-9);
  auto expect_one = [](const std::vector<std::string>& errors, const std::string& path,
                       const std::string& what) {
    ASSERT_EQ(errors.size(), 1u) << (errors.empty() ? "" : errors[0]);
    EXPECT_NE(errors[0].find(path), std::string::npos) << errors[0];
    EXPECT_NE(errors[0].find(what), std::string::npos) << errors[0];
  };
  expect_one(fissure::testing::errors(with("{fields: {pressure_loads: {absolute: 1 mm}}}")),
             "coupling.iteration.fields.pressure_loads.absolute", "expected a pressure");
  expect_one(fissure::testing::errors(with("{fields: {apertures: {relative: 1e-3}}}")),
             "coupling.iteration.fields",
             "found 'apertures', which no process of physics "
             "exchanges; expected one of: continuum_interface_loads.traction, pressure_loads");
  expect_one(fissure::testing::errors(with("{fields: {pressure_loads: {relative: 2}}}")),
             "coupling.iteration.fields.pressure_loads.relative", "expected a number in (0, 1)");
  expect_one(fissure::testing::errors(with("{fields: {pressure_loads: {tolerance: 2}}}")),
             "coupling.iteration.fields.pressure_loads.tolerance", "expected one of");
}
