// Random numbers and the distributions of joint sets and DFN families
// (docs/rock-mass.md section 3): a seeded generator whose streams are fixed
// by (seed, stream id), samplers for orientations, trace lengths (also
// length-biased, for the Poisson process of fractures that reach the domain)
// and apertures, and the moments and CDFs that the density estimate and the
// statistical tests need.
//
// Reproducibility: the engine is std::mt19937_64 (its output sequence is fixed
// by the C++ standard) and every transformation is written here, not left to
// std:: distributions (whose algorithms differ between standard libraries).
// The same seed therefore gives the same fractures wherever the C library's
// elementary functions (log, cos, ...) round alike.
#pragma once

#include <cstdint>
#include <random>

#include "rockmass/rock_mass_spec.h"

namespace fissure {

class Rng {
 public:
  /// Independent streams for one seed: stream ids name the joint set or DFN
  /// family, so adding a family does not change the others.
  Rng(std::uint64_t seed, std::uint64_t stream);

  double uniform();       ///< [0, 1), 53 random bits
  double uniform_open();  ///< (0, 1)
  double normal();        ///< standard normal (Marsaglia's polar method)
  /// Poisson(mean) by Knuth's product of uniforms, in chunks of mean <= 16
  /// (a sum of independent Poisson variables is Poisson): exact, O(mean).
  long poisson(double mean);

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

/// Moment E[l^k] of a length distribution (k = 0, 1, 2, ...).
double length_moment(const DistributionSpec& d, int k);

/// A length from the density proportional to l^k p(l) (k = 0: p itself; k = 1
/// and 2: the length-biased densities used to sample the fractures that reach
/// a window, dfn_generator.cpp).
double sample_length(const DistributionSpec& d, int k, Rng& rng);

/// CDF of a length distribution.
double length_cdf(const DistributionSpec& d, double l);

/// A trace direction in [0, pi) (rad). Von Mises is axial: the deviation
/// phi = theta - mean in (-pi/2, pi/2] has density exp(kappa cos 2 phi) /
/// (pi I0(kappa)), i.e. 2 phi is circular von Mises (Best and Fisher 1979).
double sample_orientation(const DistributionSpec& d, Rng& rng);

/// The deviation of a direction from the distribution's mean, in
/// [-pi/2, pi/2) (von Mises, fixed); for uniform, the direction in [0, pi).
double orientation_deviation(const DistributionSpec& d, double theta);

/// CDF of orientation_deviation (von Mises by Simpson quadrature of the
/// density; uniform on [0, pi)).
double orientation_cdf(const DistributionSpec& d, double deviation);

/// Probability of each of `bins` equal direction bins covering [0, pi).
std::vector<double> orientation_weights(const DistributionSpec& d, int bins);

/// An aperture for a fracture of length `length` (m).
double sample_aperture(const DistributionSpec& d, double length, Rng& rng);

/// CDF of the aperture of a constant or log-normal distribution.
double aperture_cdf(const DistributionSpec& d, double e);

/// Log-normal parameters (mu, sigma) of ln X from the mean and standard
/// deviation of X: sigma^2 = ln(1 + std^2 / mean^2), mu = ln mean - sigma^2/2.
std::pair<double, double> log_normal_parameters(double mean, double std);

}  // namespace fissure
