// The closed-form poroelastic references (tests/support/poroelastic_solutions)
// against the tables of verification.md (j) Terzaghi and (k) Mandel, and the
// self-checks of (k): the load carried at all times, the undrained start and
// the drained end. Catalogue values are printed to 5-6 digits, so the
// tolerances are half a unit of the last printed digit unless stated.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/support/poroelastic_solutions.h"

using namespace fissure::test;

namespace {

constexpr double kPi = std::numbers::pi;

/// The time of the time factor T_v (Terzaghi) or c t / a^2 (Mandel).
double terzaghi_time(const Terzaghi& s, double tv) {
  return tv * s.height * s.height / s.consolidation_coefficient();
}
double mandel_time(const Mandel& s, double tv) {
  return tv * s.a * s.a / s.consolidation_coefficient();
}

TEST(PoroelasticSolutions, TerzaghiDerivedValuesMatchTheCatalogue) {
  const Terzaghi s;
  EXPECT_NEAR(s.constrained_modulus(), 1.2e9, 1);
  EXPECT_NEAR(s.consolidation_coefficient(), 1.07143e-3, 0.5e-8);
  EXPECT_NEAR(s.initial_pressure(), 0.892857e6, 0.5);
  EXPECT_NEAR(s.time_factor(terzaghi_time(s, 0.2)), 0.2, 1e-15);
  // w0 (undrained, at 0+) and w_inf (drained).
  EXPECT_NEAR(s.settlement(0), 8.92857e-4, 0.5e-9);
  EXPECT_NEAR(s.settlement(terzaghi_time(s, 100)), 8.33333e-3, 0.5e-8);
}

TEST(PoroelasticSolutions, TerzaghiMatchesTheCataloguesTable) {
  struct Row {
    double tv, p_base, p_middle, u;
  };
  const std::vector<Row> table = {{0.05, 0.99687, 0.88615, 0.25231},
                                  {0.2, 0.77231, 0.55318, 0.50409},
                                  {0.5, 0.37078, 0.26219, 0.76395},
                                  {1.0, 0.10798, 0.07635, 0.93126}};
  const Terzaghi s;
  const double p0 = s.initial_pressure();
  for (const Row& row : table) {
    SCOPED_TRACE(row.tv);
    const double t = terzaghi_time(s, row.tv);
    EXPECT_NEAR(s.pressure(s.height, t) / p0, row.p_base, 1e-5);
    EXPECT_NEAR(s.pressure(s.height / 2, t) / p0, row.p_middle, 1e-5);
    EXPECT_NEAR(s.degree_of_consolidation(t), row.u, 1e-5);
  }
}

// t = 0 gives the t -> 0+ limit, which the series approaches: p0 away from the
// drained top, and U ~ sqrt(4 T_v / pi) at small T_v.
TEST(PoroelasticSolutions, TerzaghiStartsUndrained) {
  const Terzaghi s;
  const double p0 = s.initial_pressure();
  EXPECT_EQ(s.pressure(s.height, 0), p0);
  EXPECT_EQ(s.pressure(0, 0), 0);
  EXPECT_EQ(s.degree_of_consolidation(0), 0);
  const double t = terzaghi_time(s, 1e-6);
  EXPECT_NEAR(s.pressure(s.height / 2, t) / p0, 1, 1e-12);
  EXPECT_EQ(s.pressure(0, t), 0);
  EXPECT_NEAR(s.degree_of_consolidation(t), std::sqrt(4e-6 / kPi), 1e-12);
}

TEST(PoroelasticSolutions, MandelDerivedValuesMatchTheCatalogue) {
  const Mandel s;
  EXPECT_NEAR(s.bulk_modulus(), 0.55556e9, 5e3);
  EXPECT_NEAR(s.shear_modulus(), 0.41667e9, 5e3);
  EXPECT_NEAR(s.undrained_bulk_modulus(), 2.55556e9, 5e3);
  EXPECT_NEAR(s.skempton(), 0.782609, 0.5e-6);
  EXPECT_NEAR(s.undrained_poisson_ratio(), 0.422680, 0.5e-6);
  EXPECT_NEAR(s.consolidation_coefficient(), 0.0714286, 0.5e-7);
  EXPECT_NEAR(s.initial_pressure(), 0.371134e6, 0.5);

  // The four equivalent forms of c in (k).
  const double kappa = s.mobility, b = s.skempton(), g = s.shear_modulus();
  const double nu = s.poisson_ratio, nu_u = s.undrained_poisson_ratio();
  const double m = s.biot_modulus, alpha = s.biot;
  const double lambda = s.bulk_modulus() - 2 * g / 3;
  const double lambda_u = s.undrained_bulk_modulus() - 2 * g / 3;
  const double c = s.consolidation_coefficient();
  EXPECT_NEAR(
      2 * kappa * b * b * g * (1 - nu) * (1 + nu_u) * (1 + nu_u) / (9 * (1 - nu_u) * (nu_u - nu)),
      c, 1e-12 * c);
  EXPECT_NEAR(kappa * m * (lambda + 2 * g) / (lambda_u + 2 * g), c, 1e-12 * c);
  EXPECT_NEAR(2 * kappa * g * (1 - nu) * (nu_u - nu) /
                  (alpha * alpha * (1 - 2 * nu) * (1 - 2 * nu) * (1 - nu_u)),
              c, 1e-12 * c);
}

TEST(PoroelasticSolutions, MandelRootsMatchTheCatalogue) {
  const Mandel s;
  const std::vector<double> expected = {1.370407, 4.652634, 7.818395, 10.970206, 14.117453};
  const std::vector<double> roots = s.roots(5);
  ASSERT_EQ(roots.size(), expected.size());
  const double slope = (1 - s.poisson_ratio) / (s.undrained_poisson_ratio() - s.poisson_ratio);
  for (int n = 1; n <= 5; ++n) {
    const double x = roots[n - 1];
    SCOPED_TRACE(n);
    EXPECT_NEAR(x, expected[n - 1], 1e-6);
    EXPECT_GT(x, (n - 1) * kPi);
    EXPECT_LT(x, (n - 0.5) * kPi);
    // sin - slope x cos avoids the pole of tan next to the root.
    EXPECT_NEAR(std::sin(x) - slope * x * std::cos(x), 0, 1e-14 * x);
  }
  // From the cache: the same roots, also as the head of a longer list.
  EXPECT_EQ(s.roots(5), roots);
  EXPECT_EQ(s.roots(400).size(), 400u);
  EXPECT_EQ(s.roots(400)[4], roots[4]);
}

TEST(PoroelasticSolutions, MandelMatchesTheCataloguesOvershootTable) {
  const std::vector<double> times = {0.01, 0.05, 0.1, 0.2, 0.5, 1.0};
  const std::vector<double> centre = {1.03220, 1.07109, 1.05463, 0.91136, 0.52225, 0.20421};
  const std::vector<double> middle = {1.03179, 0.95602, 0.82582, 0.66248, 0.37509, 0.14666};
  const Mandel s;
  const double p0 = s.initial_pressure();
  for (std::size_t i = 0; i < times.size(); ++i) {
    SCOPED_TRACE(times[i]);
    const double t = mandel_time(s, times[i]);
    EXPECT_NEAR(s.pressure(0, t) / p0, centre[i], 1e-5);
    EXPECT_NEAR(s.pressure(s.a / 2, t) / p0, middle[i], 1e-5);
    EXPECT_EQ(s.pressure(s.a, t), 0);  // the drained side
  }
}

// The plates carry F on the quarter model at all t: Simpson's rule over 0..a.
TEST(PoroelasticSolutions, MandelStressCarriesTheLoadAtAllTimes) {
  const Mandel s;
  const int intervals = 2000;
  const double h = s.a / intervals;
  for (const double tv : {0.0, 1e-3, 0.01, 0.1, 1.0}) {
    SCOPED_TRACE(tv);
    const double t = mandel_time(s, tv);
    double sum = 0;
    for (int i = 0; i <= intervals; ++i) {
      const double weight = (i == 0 || i == intervals) ? 1 : (i % 2 == 1 ? 4 : 2);
      sum += weight * s.stress_yy(i * h, t);
    }
    EXPECT_NEAR(sum * h / 3, -s.force, 1e-6 * s.force);
  }
}

// t = 0 gives the undrained closed forms, which the series approaches as
// t -> 0+ (the departure grows like sqrt(c t) / a).
TEST(PoroelasticSolutions, MandelStartsUndrained) {
  const Mandel s;
  const double g = s.shear_modulus(), nu_u = s.undrained_poisson_ratio(), f = s.force;
  const double ux0 = f * nu_u / (2 * g), uy0 = -f * (1 - nu_u) / (2 * g);
  EXPECT_EQ(s.pressure(s.a / 2, 0), s.initial_pressure());
  EXPECT_EQ(s.stress_yy(s.a / 2, 0), -f / s.a);
  EXPECT_NEAR(s.displacement_x(s.a, 0), ux0, 1e-15);
  EXPECT_NEAR(s.displacement_y(s.a, 0), uy0, 1e-15);

  const double t = mandel_time(s, 1e-8);
  EXPECT_NEAR(s.pressure(s.a / 2, t) / s.initial_pressure(), 1, 1e-4);
  EXPECT_NEAR(s.stress_yy(s.a / 2, t) / (-f / s.a), 1, 1e-4);
  EXPECT_NEAR(s.displacement_x(s.a, t) / ux0, 1, 1e-4);
  EXPECT_NEAR(s.displacement_y(s.a, t) / uy0, 1, 1e-4);
}

// As t -> infinity the pressure dissipates and the drained elastic solution
// remains: u_x(a) = F nu / (2 G), u_y(b) = -F (1 - nu) b / (2 G a).
TEST(PoroelasticSolutions, MandelRecoversTheDrainedSolutionAsTimeGoesToInfinity) {
  const Mandel s;
  const double g = s.shear_modulus(), nu = s.poisson_ratio, f = s.force;
  const double t = mandel_time(s, 50);
  EXPECT_NEAR(s.displacement_x(s.a, t), f * nu / (2 * g), 1e-12 * f / g);
  EXPECT_NEAR(s.displacement_y(s.a, t), -f * (1 - nu) / (2 * g), 1e-12 * f / g);
  EXPECT_NEAR(s.pressure(0, t), 0, 1e-12 * s.initial_pressure());
  EXPECT_NEAR(s.stress_yy(0, t), -f / s.a, 1e-12 * f / s.a);
  // Consolidation only moves u_x(a) towards the drained value, from the undrained one.
  EXPECT_GT(s.displacement_x(s.a, mandel_time(s, 0.1)), s.displacement_x(s.a, t));
}

}  // namespace
