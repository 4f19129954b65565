#include "flow/rev/poisson_dfn.h"

#include <cmath>
#include <random>

namespace fissure::flow {

namespace {

/// Inverse CDF of the truncated power law n(l) ~ l^-a on [lo, hi].
double power_law_length(double u, double lo, double hi, double a) {
  if (std::abs(a - 1) < 1e-12) return lo * std::pow(hi / lo, u);
  const double b = 1 - a;
  return std::pow(std::pow(lo, b) + u * (std::pow(hi, b) - std::pow(lo, b)), 1 / b);
}

}  // namespace

double mean_length(const DfnSet& s) {
  const double lo = s.length_min, hi = s.length_max, a = s.length_exponent;
  if (hi <= lo) return lo;
  // E[l] = int l^(1-a) / int l^-a over [lo, hi].
  auto integral = [](double lo, double hi, double p) {
    return std::abs(p + 1) < 1e-12 ? std::log(hi / lo)
                                   : (std::pow(hi, p + 1) - std::pow(lo, p + 1)) / (p + 1);
  };
  return integral(lo, hi, 1 - a) / integral(lo, hi, -a);
}

std::vector<Trace> generate_traces(const PoissonDfn& dfn, int realization) {
  std::mt19937_64 rng(dfn.seed * 1000003ULL + static_cast<unsigned long>(realization));
  std::uniform_real_distribution<double> uniform(0, 1);
  std::normal_distribution<double> normal(0, 1);
  std::vector<Trace> traces;
  const double area = dfn.region * dfn.region;
  for (std::size_t k = 0; k < dfn.sets.size(); ++k) {
    const DfnSet& set = dfn.sets[k];
    // Poisson number of traces with mean P21 A / E[l].
    std::poisson_distribution<long> count(set.p21 * area / mean_length(set));
    const long n = count(rng);
    for (long i = 0; i < n; ++i) {
      const Vec2 c = dfn.centre + dfn.region * Vec2(uniform(rng) - 0.5, uniform(rng) - 0.5);
      const double angle = set.angle + set.angle_std * normal(rng);
      const double length =
          power_law_length(uniform(rng), set.length_min, std::max(set.length_max, set.length_min),
                           set.length_exponent);
      const Vec2 t(std::cos(angle), std::sin(angle));
      Trace tr;
      tr.a = c - 0.5 * length * t;
      tr.b = c + 0.5 * length * t;
      tr.aperture = set.aperture * std::pow(10.0, set.aperture_log10_std * normal(rng));
      tr.joint_set = static_cast<int>(k);
      tr.fracture = static_cast<int>(traces.size());
      traces.push_back(tr);
    }
  }
  return traces;
}

}  // namespace fissure::flow
