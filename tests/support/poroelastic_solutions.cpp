#include "tests/support/poroelastic_solutions.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace fissure::test {
namespace {

constexpr double kPi = std::numbers::pi;

// Terzaghi: at least 200 terms (verification.md (j)); then stop when the bound on the rest of
// the series is below this, relative to the leading coefficient.
constexpr int kTerzaghiMinTerms = 200;
constexpr int kMaxTerms = 100000;
constexpr double kTailTolerance = 1e-14;

/// Sum over the odd modes k = 1, 3, 5, ... of term(k) exp(-k^2 pi^2 T_v / 4), where
/// |term(k)| <= scale / k. The rest after mode k is at most b / (1 - r), with b the bound on
/// mode k + 2 and r the ratio of the exponentials of modes k + 4 and k + 2 (which falls with k).
template <class Term>
double odd_mode_sum(double tv, double scale, Term term) {
  double sum = 0;
  for (int m = 0; m < kMaxTerms; ++m) {
    const double k = 2.0 * m + 1;
    sum += term(k) * std::exp(-k * k * kPi * kPi * tv / 4);
    if (m + 1 < kTerzaghiMinTerms) continue;
    const double next = scale / (k + 2) * std::exp(-(k + 2) * (k + 2) * kPi * kPi * tv / 4);
    const double one_minus_ratio = -std::expm1(-(k + 3) * kPi * kPi * tv);
    if (next < kTailTolerance * one_minus_ratio) break;
  }
  return sum;
}

// Mandel: the terms with alpha_n^2 c t / a^2 above this are below e^-45 ~ 3e-20 and dropped;
// the rest of the series after that is then below 1e-14 relative down to c t / a^2 ~ 1e-8.
constexpr double kMandelExponentCut = 45;
constexpr int kMandelMinRoots = 400;

/// The cached roots of m, at least n of them.
const std::vector<double>& cached_roots(const Mandel& m, int n) {
  const double nu = m.poisson_ratio, nu_u = m.undrained_poisson_ratio();
  const double slope = (1 - nu) / (nu_u - nu);
  if (slope != m.root_cache_slope_) {
    m.root_cache_.clear();
    m.root_cache_slope_ = slope;
  }
  auto& roots = m.root_cache_;
  roots.reserve(n);
  // g(x) = sin x - slope x cos x has the roots of tan x = slope x without the poles. On
  // ((n-1) pi, (n-1/2) pi), (-1)^(n-1) g < 0 at the left end (just right of 0 for n = 1,
  // since slope > 1) and = 1 at the right end: bisection down to adjacent doubles.
  for (int i = static_cast<int>(roots.size()) + 1; i <= n; ++i) {
    const double sign = (i % 2 == 1) ? 1 : -1;
    double lo = (i - 1) * kPi, hi = (i - 0.5) * kPi;
    for (;;) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const double g = sign * (std::sin(mid) - slope * mid * std::cos(mid));
      (g < 0 ? lo : hi) = mid;
    }
    roots.push_back(0.5 * (lo + hi));
  }
  return roots;
}

/// Calls f(alpha_n, sin, cos, D_n, e_n) for the modes of Mandel's series at t > 0 that are not
/// negligible, D_n = alpha_n - sin cos and e_n = exp(-alpha_n^2 c t / a^2) (verification.md (k)).
template <class F>
void for_each_mandel_mode(const Mandel& m, double t, F f) {
  const double tv = m.consolidation_coefficient() * t / (m.a * m.a);
  const double needed = std::ceil(std::sqrt(kMandelExponentCut / tv) / kPi) + 1;
  const int n = static_cast<int>(std::clamp<double>(needed, kMandelMinRoots, kMaxTerms));
  for (const double alpha : cached_roots(m, n)) {
    const double exponent = alpha * alpha * tv;
    if (exponent > kMandelExponentCut) break;
    const double s = std::sin(alpha), c = std::cos(alpha);
    f(alpha, s, c, alpha - s * c, std::exp(-exponent));
  }
}

}  // namespace

// ---- Terzaghi (verification.md (j)) ----

double Terzaghi::constrained_modulus() const {
  const double nu = poisson_ratio;
  return young_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
}

double Terzaghi::consolidation_coefficient() const {
  return mobility / (1 / biot_modulus + biot * biot / constrained_modulus());
}

double Terzaghi::initial_pressure() const {
  return biot * load / (biot * biot + constrained_modulus() / biot_modulus);
}

double Terzaghi::time_factor(double t) const {
  return consolidation_coefficient() * t / (height * height);
}

double Terzaghi::pressure(double z, double t) const {
  // The series does not converge at t = 0; its limit is p0 inside and 0 on the drained top.
  if (t <= 0) return z > 0 ? initial_pressure() : 0;
  const double sum = odd_mode_sum(time_factor(t), 4 / kPi, [&](double k) {
    return 4 / kPi / k * std::sin(k * kPi * z / (2 * height));
  });
  return initial_pressure() * sum;
}

double Terzaghi::degree_of_consolidation(double t) const {
  if (t <= 0) return 0;
  return 1 - odd_mode_sum(time_factor(t), 8 / (kPi * kPi),
                          [](double k) { return 8 / (k * k * kPi * kPi); });
}

double Terzaghi::settlement(double t) const {
  // Undrained: the fluid stiffens the column to K_v + alpha^2 M; drained: K_v alone.
  const double w0 = load * height / (constrained_modulus() + biot * biot * biot_modulus);
  const double w_inf = load * height / constrained_modulus();
  return w0 + (w_inf - w0) * degree_of_consolidation(t);
}

// ---- Mandel (verification.md (k)) ----

double Mandel::bulk_modulus() const {
  return young_modulus / (3 * (1 - 2 * poisson_ratio));
}

double Mandel::shear_modulus() const {
  return young_modulus / (2 * (1 + poisson_ratio));
}

double Mandel::undrained_bulk_modulus() const {
  return bulk_modulus() + biot * biot * biot_modulus;
}

double Mandel::undrained_poisson_ratio() const {
  const double ku = undrained_bulk_modulus(), g = shear_modulus();
  return (3 * ku - 2 * g) / (2 * (3 * ku + g));
}

double Mandel::skempton() const {
  return biot * biot_modulus / undrained_bulk_modulus();
}

double Mandel::consolidation_coefficient() const {
  // The second of the four equivalent forms of (k): kappa / (1/M + alpha^2 / K_v).
  const double kv = bulk_modulus() + 4 * shear_modulus() / 3;
  return mobility / (1 / biot_modulus + biot * biot / kv);
}

double Mandel::initial_pressure() const {
  return force * skempton() * (1 + undrained_poisson_ratio()) / (3 * a);
}

std::vector<double> Mandel::roots(int n) const {
  if (n <= 0) return {};
  const auto& all = cached_roots(*this, n);
  return {all.begin(), all.begin() + n};
}

double Mandel::pressure(double x, double t) const {
  // t -> 0+: p0 inside, 0 on the drained side x = a (where every term vanishes for t > 0).
  if (t <= 0) return x < a ? initial_pressure() : 0;
  double sum = 0;
  for_each_mandel_mode(*this, t, [&](double alpha, double s, double c, double d, double e) {
    sum += s / d * (std::cos(alpha * x / a) - c) * e;
  });
  return 2 * initial_pressure() * sum;
}

double Mandel::stress_yy(double x, double t) const {
  if (t <= 0) return -force / a;
  const double nu = poisson_ratio, nu_u = undrained_poisson_ratio();
  double cos_sum = 0, sin_cos_sum = 0;
  for_each_mandel_mode(*this, t, [&](double alpha, double s, double c, double d, double e) {
    cos_sum += s / d * std::cos(alpha * x / a) * e;
    sin_cos_sum += s * c / d * e;
  });
  return -force / a - 2 * force * (nu_u - nu) / (a * (1 - nu)) * cos_sum +
         2 * force / a * sin_cos_sum;
}

double Mandel::displacement_x(double x, double t) const {
  const double g = shear_modulus(), nu_u = undrained_poisson_ratio();
  if (t <= 0) return force * nu_u * x / (2 * g * a);
  double sin_cos_sum = 0, sin_x_sum = 0;
  for_each_mandel_mode(*this, t, [&](double alpha, double s, double c, double d, double e) {
    sin_cos_sum += s * c / d * e;
    sin_x_sum += c / d * std::sin(alpha * x / a) * e;
  });
  return (force * poisson_ratio / (2 * g * a) - force * nu_u / (g * a) * sin_cos_sum) * x +
         force / g * sin_x_sum;
}

double Mandel::displacement_y(double y, double t) const {
  const double g = shear_modulus(), nu_u = undrained_poisson_ratio();
  if (t <= 0) return -force * (1 - nu_u) * y / (2 * g * a);
  double sin_cos_sum = 0;
  for_each_mandel_mode(*this, t, [&](double, double s, double c, double d, double e) {
    sin_cos_sum += s * c / d * e;
  });
  return (-force * (1 - poisson_ratio) / (2 * g * a) + force * (1 - nu_u) / (g * a) * sin_cos_sum) *
         y;
}

double BookerSavvidou::temperature(double r, double t) const {
  const double kappa = conductivity / heat_capacity;
  return power / (4 * std::numbers::pi * conductivity * r) *
         std::erfc(r / (2 * std::sqrt(kappa * t)));
}

double BookerSavvidou::pressure(double r, double t) const {
  // c and X of verification.md (l): the drained constrained storage.
  const double e = young_modulus, nu = poisson_ratio;
  const double k_bulk = e / (3 * (1 - 2 * nu)), g = e / (2 * (1 + nu));
  const double kv = k_bulk + 4 * g / 3, storage = 1 / biot_modulus + 1 / kv;
  const double c = permeability / viscosity / storage;
  const double x = (fluid_expansion - 3 * k_bulk * expansion / kv) / storage;
  const double kappa = conductivity / heat_capacity;
  return x * power * kappa / (4 * std::numbers::pi * conductivity * r * (kappa - c)) *
         (std::erfc(r / (2 * std::sqrt(kappa * t))) - std::erfc(r / (2 * std::sqrt(c * t))));
}

std::string BookerSavvidou::scene(double fine, double coarse, double step_years,
                                  double grading) const {
  std::ostringstream s;
  s << "name: booker_savvidou\nphysics: [continuum]\ngravity: [0, 0]\nmaterials:\n"
    << "  - {name: rock, density: 2500, young_modulus: " << young_modulus
    << ", poisson_ratio: " << poisson_ratio << "}\ntime: {end: 1 yr}\ncontinuum:\n"
    << "  geometry: axisymmetric\n  domain: [[0, 0], [60, 0], [60, 60], [0, 60]]\n"
    << "  mesh: {element_size: " << coarse << " m, fine_element_size: " << fine
    << " m, size_grading: " << grading << ", max_elements: 1e6}\n  materials:\n"
    << "    - {name: rock, biot_modulus: " << biot_modulus << ", permeability: " << permeability
    << " m^2, thermal_expansion: " << expansion << ", fluid_thermal_expansion: " << fluid_expansion
    << ", conductivity: " << conductivity << " W/m/K, heat_capacity: " << heat_capacity
    << " J/m^3/K}\n  fluid: {viscosity: " << viscosity << " Pa*s}\n  initial: {temperature: 0}\n"
    << "  sources: [{name: heater, point: [0, 0], power: " << power / 2 << " W}]\n"
    << "  conditions:\n    - {boundary: bottom, displacement: [free, 0]}\n"
    << "    - {boundary: right, temperature: 0}\n    - {boundary: top, temperature: 0}\n"
    << "    - {boundary: right, pressure: 0}\n    - {boundary: top, pressure: 0}\n"
    << "  scheme: monolithic\n  time_step: " << step_years << " yr\n";
  return s.str();
}

}  // namespace fissure::test
