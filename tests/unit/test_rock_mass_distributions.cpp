// The distributions of rockmass/distributions.h: reproducible random
// streams, the moments used to turn P21 into P20 (against quadrature of the
// CDFs), the length-biased samplers (their sample means against the exact
// biased means E[l^(k+1)] / E[l^k]), the Poisson sampler (mean and variance),
// and the direction weights used by the size estimate. The samplers' full
// distributions are tested by Kolmogorov-Smirnov in
// tests/verification/test_dfn_statistics.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rockmass/distributions.h"

namespace fissure {
namespace {

using Type = DistributionSpec::Type;
constexpr double kPi = 3.14159265358979323846;

DistributionSpec make(Type t, double a = 0, double b = 0, double c = 0) {
  DistributionSpec d;
  d.type = t;
  switch (t) {
    case Type::Constant:
      d.value = a;
      break;
    case Type::Uniform:
      d.min = a;
      d.max = b;
      break;
    case Type::Exponential:
      d.mean = a;
      break;
    case Type::LogNormal:
      d.mean = a;
      d.std = b;
      break;
    case Type::TruncatedPowerLaw:
      d.exponent = a;
      d.min = b;
      d.max = c;
      break;
    default:
      break;
  }
  return d;
}

std::vector<DistributionSpec> length_cases() {
  return {make(Type::Constant, 2.5),
          make(Type::Uniform, 0.5, 4),
          make(Type::Exponential, 1.7),
          make(Type::LogNormal, 3, 1.5),
          make(Type::TruncatedPowerLaw, 2.5, 0.5, 20),
          make(Type::TruncatedPowerLaw, 1, 0.5, 20),
          make(Type::TruncatedPowerLaw, 2, 1, 10),
          make(Type::TruncatedPowerLaw, 3, 1, 10)};
}

/// E[l^k] by integrating the CDF: E[l^k] = int k l^(k-1) (1 - F(l)) dl.
double moment_by_quadrature(const DistributionSpec& d, int k) {
  const double hi = d.type == Type::Exponential ? 60 * d.mean
                    : d.type == Type::LogNormal ? 200 * d.mean
                    : d.type == Type::Constant  ? d.value
                                                : d.max;
  if (d.type == Type::Constant) return std::pow(d.value, k);
  const int n = 400000;
  const double h = hi / n;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double l = (i + 0.5) * h;
    s += k * std::pow(l, k - 1) * (1 - length_cdf(d, l)) * h;
  }
  return s;
}

TEST(RockMassDistributions, StreamsAreReproducibleAndIndependent) {
  Rng a(42, 3), b(42, 3), c(42, 4), d(43, 3);
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
  EXPECT_NE(Rng(42, 3).uniform(), c.uniform());
  EXPECT_NE(Rng(42, 3).uniform(), d.uniform());
}

TEST(RockMassDistributions, MomentsMatchQuadratureOfTheCdf) {
  for (const DistributionSpec& d : length_cases())
    for (int k : {1, 2}) {
      const double exact = length_moment(d, k);
      EXPECT_NEAR(moment_by_quadrature(d, k) / exact, 1.0, 1e-4)
          << "type " << static_cast<int>(d.type) << " k " << k;
    }
}

TEST(RockMassDistributions, LengthBiasedSamplesHaveTheBiasedMean) {
  // The density l^k p(l) / E[l^k] has mean E[l^(k+1)] / E[l^k]. Sample mean of
  // n = 200000 draws: the standard error is below 0.5 % of the mean for these
  // cases; the tolerance is 5 standard errors.
  const int n = 200000;
  for (const DistributionSpec& d : length_cases()) {
    if (d.type == Type::Constant) continue;
    for (int k : {0, 1, 2}) {
      Rng rng(7, static_cast<std::uint64_t>(k));
      double s = 0, s2 = 0;
      for (int i = 0; i < n; ++i) {
        const double l = sample_length(d, k, rng);
        s += l;
        s2 += l * l;
      }
      const double mean = s / n, sd = std::sqrt(std::max(s2 / n - mean * mean, 0.0));
      const double expected = length_moment(d, k + 1) / length_moment(d, k);
      EXPECT_NEAR(mean, expected, 5 * sd / std::sqrt(n))
          << "type " << static_cast<int>(d.type) << " k " << k;
    }
  }
}

TEST(RockMassDistributions, PoissonHasEqualMeanAndVariance) {
  for (double mean : {0.3, 5.0, 40.0, 2500.0}) {
    Rng rng(11, static_cast<std::uint64_t>(mean));
    const int n = 20000;
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
      const double x = static_cast<double>(rng.poisson(mean));
      s += x;
      s2 += x * x;
    }
    const double m = s / n, var = s2 / n - m * m;
    // Standard error of the mean sqrt(mean / n); of the variance about
    // mean sqrt(2 / n) (plus the fourth-cumulant term, small here).
    EXPECT_NEAR(m, mean, 5 * std::sqrt(mean / n)) << mean;
    EXPECT_NEAR(var / mean, 1.0, 5 * std::sqrt(2.0 / n) + 5 / std::sqrt(mean * n)) << mean;
  }
}

TEST(RockMassDistributions, OrientationsStayInHalfTurn) {
  DistributionSpec vm;
  vm.type = Type::VonMises;
  vm.mean = 170 * kPi / 180;  // the mean near pi: samples wrap to small angles
  vm.kappa = 5;
  Rng rng(1, 1);
  int wrapped = 0;
  for (int i = 0; i < 10000; ++i) {
    const double t = sample_orientation(vm, rng);
    ASSERT_GE(t, 0.0);
    ASSERT_LT(t, kPi);
    if (t < kPi / 2) ++wrapped;
    const double phi = orientation_deviation(vm, t);
    ASSERT_GE(phi, -kPi / 2);
    ASSERT_LT(phi, kPi / 2);
  }
  EXPECT_GT(wrapped, 100);
  EXPECT_NEAR(orientation_cdf(vm, 0.0), 0.5, 1e-9);
  EXPECT_NEAR(orientation_cdf(vm, kPi / 2), 1.0, 1e-9);
}

TEST(RockMassDistributions, DirectionWeightsSumToOne) {
  DistributionSpec vm;
  vm.type = Type::VonMises;
  vm.mean = 0.3;
  vm.kappa = 20;
  for (const DistributionSpec& d : {vm, make(Type::Uniform), make(Type::Constant, 1.0)}) {
    const std::vector<double> w = orientation_weights(d, 180);
    double s = 0;
    for (double x : w) s += x;
    EXPECT_NEAR(s, 1.0, 1e-12);
  }
}

TEST(RockMassDistributions, LengthCorrelatedApertures) {
  DistributionSpec d;
  d.type = Type::LengthCorrelated;
  d.factor = 2e-5;
  d.exponent = 0.5;
  Rng rng(3, 3);
  EXPECT_DOUBLE_EQ(sample_aperture(d, 4.0, rng), 4e-5);
  const auto [mu, sigma] = log_normal_parameters(100e-6, 40e-6);
  EXPECT_NEAR(std::exp(mu + sigma * sigma / 2), 100e-6, 1e-18);
}

}  // namespace
}  // namespace fissure
