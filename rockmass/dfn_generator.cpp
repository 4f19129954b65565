#include "rockmass/dfn_generator.h"

#include <array>
#include <cmath>

namespace fissure {

FractureTrace DfnFracture::trace(int set, int joint) const {
  const Vec2 half = 0.5 * length * Vec2(std::cos(angle), std::sin(angle));
  return FractureTrace{centre - half, centre + half, set, joint, aperture};
}

double dfn_p20(const DfnFamilySpec& spec) {
  return spec.density_kind == DfnFamilySpec::Density::P20
             ? spec.density
             : spec.density / length_moment(spec.length, 1);
}

namespace {

/// Weights W H, (W + H) E[l], E[l^2] of the three length components.
std::array<double, 3> window_weights(const DfnFamilySpec& spec, const Box& domain) {
  const double w = domain.size().x(), h = domain.size().y();
  return {w * h, (w + h) * length_moment(spec.length, 1), length_moment(spec.length, 2)};
}

}  // namespace

double expected_dfn_fractures(const DfnFamilySpec& spec, const Box& domain) {
  const std::array<double, 3> c = window_weights(spec, domain);
  return dfn_p20(spec) * (c[0] + c[1] + c[2]);
}

std::vector<DfnFracture> generate_dfn_family(const DfnFamilySpec& spec, const Box& domain,
                                             Rng& rng) {
  const std::array<double, 3> c = window_weights(spec, domain);
  const double total = c[0] + c[1] + c[2];
  const long n = rng.poisson(dfn_p20(spec) * total);
  std::vector<DfnFracture> fractures;
  fractures.reserve(n);
  for (long i = 0; i < n; ++i) {
    DfnFracture f;
    // 1. Length: which of the three components, then a length from it.
    const double u = rng.uniform() * total;
    const int k = u < c[0] ? 0 : u < c[0] + c[1] ? 1 : 2;
    f.length = sample_length(spec.length, k, rng);
    // 2. Centre uniform in the box grown by half the length.
    const double r = 0.5 * f.length;
    f.centre = Vec2(domain.lo.x() - r + rng.uniform() * (domain.size().x() + 2 * r),
                    domain.lo.y() - r + rng.uniform() * (domain.size().y() + 2 * r));
    // 3. Direction and aperture.
    f.angle = sample_orientation(spec.orientation, rng);
    f.aperture = sample_aperture(spec.aperture, f.length, rng);
    fractures.push_back(f);
  }
  return fractures;
}

}  // namespace fissure
