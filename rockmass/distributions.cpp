#include "rockmass/distributions.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace fissure {

namespace {

using Type = DistributionSpec::Type;
constexpr double kPi = 3.14159265358979323846;

/// SplitMix64 (Steele, Lea and Flood 2014): turns (seed, stream) into a
/// well-mixed engine seed.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// --- truncated power law p(l) ~ l^-c on [lo, hi] -----------------------------

/// Integral of l^p from lo to x.
double power_integral(double p, double lo, double x) {
  if (std::abs(p + 1) < 1e-12) return std::log(x / lo);
  return (std::pow(x, p + 1) - std::pow(lo, p + 1)) / (p + 1);
}

double sample_power_law(double c, double lo, double hi, double u) {
  if (std::abs(1 - c) < 1e-12) return lo * std::pow(hi / lo, u);
  const double a = std::pow(lo, 1 - c), b = std::pow(hi, 1 - c);
  return std::clamp(std::pow(a + u * (b - a), 1 / (1 - c)), lo, hi);
}

// --- von Mises -------------------------------------------------------------

/// Circular von Mises deviate on (-pi, pi] (Best and Fisher 1979,
/// Appl. Statist. 28:152; the rejection scheme of Fisher 1993, sec. 3.3.6).
double sample_von_mises(double kappa, Rng& rng) {
  if (kappa < 1e-8) return kPi * (2 * rng.uniform() - 1);
  if (kappa > 1e5) return std::clamp(rng.normal() / std::sqrt(kappa), -kPi, kPi);
  const double tau = 1 + std::sqrt(1 + 4 * kappa * kappa);
  const double rho = (tau - std::sqrt(2 * tau)) / (2 * kappa);
  const double r = (1 + rho * rho) / (2 * rho);
  double f = 0;
  for (;;) {
    const double z = std::cos(kPi * rng.uniform());
    f = (1 + r * z) / (r + z);
    const double c = kappa * (r - f);
    const double u2 = rng.uniform_open();
    if (c * (2 - c) - u2 > 0 || std::log(c / u2) + 1 - c >= 0) break;
  }
  const double theta = std::acos(std::clamp(f, -1.0, 1.0));
  return rng.uniform() < 0.5 ? -theta : theta;
}

/// Integral of exp(kappa (cos t - 1)) over [-pi, psi], composite Simpson.
double von_mises_integral(double kappa, double psi) {
  const int n = 2 * (1024 + static_cast<int>(100 * std::sqrt(kappa)));
  const double a = -kPi, h = (psi - a) / n;
  if (h <= 0) return 0;
  auto g = [kappa](double t) { return std::exp(kappa * (std::cos(t) - 1)); };
  double s = g(a) + g(psi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * g(a + i * h);
  return s * h / 3;
}

double wrap_axis(double a) {  // to [-pi/2, pi/2)
  double r = std::fmod(a + kPi / 2, kPi);
  if (r < 0) r += kPi;
  return r - kPi / 2;
}

}  // namespace

// --- Rng ----------------------------------------------------------------------

Rng::Rng(std::uint64_t seed, std::uint64_t stream)
    : engine_(splitmix64(splitmix64(seed) ^ splitmix64(stream + 0x632be59bd9b4e019ULL))) {}

double Rng::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double Rng::uniform_open() {
  return (static_cast<double>(engine_() >> 12) + 0.5) * 0x1.0p-52;
}

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = 2 * uniform() - 1;
    v = 2 * uniform() - 1;
    s = u * u + v * v;
  } while (s >= 1 || s == 0);
  const double f = std::sqrt(-2 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return u * f;
}

long Rng::poisson(double mean) {
  long n = 0;
  while (mean > 0) {
    const double chunk = std::min(mean, 16.0);
    mean -= chunk;
    const double limit = std::exp(-chunk);
    double product = uniform_open();
    while (product > limit) {
      ++n;
      product *= uniform_open();
    }
  }
  return n;
}

// --- lengths ------------------------------------------------------------------

std::pair<double, double> log_normal_parameters(double mean, double std) {
  const double s2 = std::log(1 + (std * std) / (mean * mean));
  return {std::log(mean) - s2 / 2, std::sqrt(s2)};
}

double length_moment(const DistributionSpec& d, int k) {
  switch (d.type) {
    case Type::Uniform:
      return (std::pow(d.max, k + 1) - std::pow(d.min, k + 1)) / ((k + 1) * (d.max - d.min));
    case Type::Exponential: {
      double m = 1;  // k! mean^k
      for (int i = 1; i <= k; ++i) m *= i * d.mean;
      return m;
    }
    case Type::LogNormal: {
      const auto [mu, sigma] = log_normal_parameters(d.mean, d.std);
      return std::exp(k * mu + 0.5 * k * k * sigma * sigma);
    }
    case Type::TruncatedPowerLaw:
      return power_integral(k - d.exponent, d.min, d.max) /
             power_integral(-d.exponent, d.min, d.max);
    default:
      return std::pow(d.value, k);
  }
}

double sample_length(const DistributionSpec& d, int k, Rng& rng) {
  switch (d.type) {
    case Type::Uniform: {
      const double a = std::pow(d.min, k + 1), b = std::pow(d.max, k + 1);
      return std::clamp(std::pow(a + rng.uniform() * (b - a), 1.0 / (k + 1)), d.min, d.max);
    }
    case Type::Exponential: {  // Gamma(k + 1, mean): a sum of k + 1 exponentials
      double product = 1;
      for (int i = 0; i <= k; ++i) product *= rng.uniform_open();
      return -d.mean * std::log(product);
    }
    case Type::LogNormal: {  // l^k times a log-normal is log-normal, mu + k sigma^2
      const auto [mu, sigma] = log_normal_parameters(d.mean, d.std);
      return std::exp(mu + k * sigma * sigma + sigma * rng.normal());
    }
    case Type::TruncatedPowerLaw:
      return sample_power_law(d.exponent - k, d.min, d.max, rng.uniform());
    default:
      return d.value;
  }
}

double length_cdf(const DistributionSpec& d, double l) {
  switch (d.type) {
    case Type::Uniform:
      return std::clamp((l - d.min) / (d.max - d.min), 0.0, 1.0);
    case Type::Exponential:
      return l <= 0 ? 0 : 1 - std::exp(-l / d.mean);
    case Type::LogNormal: {
      const auto [mu, sigma] = log_normal_parameters(d.mean, d.std);
      return l <= 0 ? 0 : normal_cdf((std::log(l) - mu) / sigma);
    }
    case Type::TruncatedPowerLaw:
      if (l <= d.min) return 0;
      if (l >= d.max) return 1;
      return power_integral(-d.exponent, d.min, l) / power_integral(-d.exponent, d.min, d.max);
    default:
      return l < d.value ? 0 : 1;
  }
}

// --- orientations -------------------------------------------------------------

double sample_orientation(const DistributionSpec& d, Rng& rng) {
  double theta = d.value;
  if (d.type == Type::Uniform)
    theta = kPi * rng.uniform();
  else if (d.type == Type::VonMises)
    theta = d.mean + 0.5 * sample_von_mises(d.kappa, rng);
  theta = std::fmod(theta, kPi);
  return theta < 0 ? theta + kPi : theta;
}

double orientation_deviation(const DistributionSpec& d, double theta) {
  if (d.type == Type::Uniform) {
    const double t = std::fmod(theta, kPi);
    return t < 0 ? t + kPi : t;
  }
  return wrap_axis(theta - (d.type == Type::VonMises ? d.mean : d.value));
}

double orientation_cdf(const DistributionSpec& d, double deviation) {
  if (d.type == Type::Uniform) return std::clamp(deviation / kPi, 0.0, 1.0);
  if (d.type != Type::VonMises) return deviation < 0 ? 0 : 1;
  const double psi = std::clamp(2 * deviation, -kPi, kPi);
  return von_mises_integral(d.kappa, psi) / von_mises_integral(d.kappa, kPi);
}

std::vector<double> orientation_weights(const DistributionSpec& d, int bins) {
  std::vector<double> w(bins, 0.0);
  const double width = kPi / bins;
  if (d.type == Type::Uniform) {
    std::fill(w.begin(), w.end(), 1.0 / bins);
  } else if (d.type == Type::VonMises) {
    double sum = 0;
    for (int b = 0; b < bins; ++b) {
      const double phi = wrap_axis((b + 0.5) * width - d.mean);
      w[b] = std::exp(d.kappa * (std::cos(2 * phi) - 1));
      sum += w[b];
    }
    for (double& x : w) x /= sum;
  } else {
    w[std::min(bins - 1, static_cast<int>(d.value / width))] = 1;
  }
  return w;
}

// --- apertures ----------------------------------------------------------------

double sample_aperture(const DistributionSpec& d, double length, Rng& rng) {
  switch (d.type) {
    case Type::LogNormal: {
      const auto [mu, sigma] = log_normal_parameters(d.mean, d.std);
      return std::exp(mu + sigma * rng.normal());
    }
    case Type::LengthCorrelated:
      return d.factor * std::pow(length, d.exponent);  // length in m: l / 1 m
    default:
      return d.value;
  }
}

double aperture_cdf(const DistributionSpec& d, double e) {
  if (d.type == Type::LogNormal) {
    const auto [mu, sigma] = log_normal_parameters(d.mean, d.std);
    return e <= 0 ? 0 : normal_cdf((std::log(e) - mu) / sigma);
  }
  return e < d.value ? 0 : 1;
}

}  // namespace fissure
