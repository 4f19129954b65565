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

/// Grown window: weights W H, (W + H) E[l], E[l^2] of its three length
/// components (the header).
std::array<double, 3> grown_weights(const DfnFamilySpec& spec, const Box& domain) {
  const double w = domain.size().x(), h = domain.size().y();
  return {w * h, (w + h) * length_moment(spec.length, 1), length_moment(spec.length, 2)};
}

/// Strip window: weights W H (forward end in B), H E[l] (exit through the
/// side facing the fracture), W E[l] (exit through the top).
std::array<double, 3> strip_weights(const DfnFamilySpec& spec, const Box& domain) {
  const double w = domain.size().x(), h = domain.size().y();
  const double mean = length_moment(spec.length, 1);
  return {w * h, h * mean, w * mean};
}

double sum(const std::array<double, 3>& c) {
  return c[0] + c[1] + c[2];
}

/// The grown window, as it always was: centres uniform in B grown by l/2.
std::vector<DfnFracture> draw_in_grown_window(const DfnFamilySpec& spec, const Box& domain,
                                              Rng& rng) {
  const std::array<double, 3> c = grown_weights(spec, domain);
  const double total = sum(c);
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

/// The strip window: every fracture kept meets B.
std::vector<DfnFracture> draw_in_strip_window(const DfnFamilySpec& spec, const Box& domain,
                                              Rng& rng) {
  const std::array<double, 3> c = strip_weights(spec, domain);
  const double total = sum(c);
  const long n = rng.poisson(dfn_p20(spec) * total);
  const Vec2 size = domain.size();
  std::vector<DfnFracture> fractures;
  for (long i = 0; i < n; ++i) {
    DfnFracture f;
    // 1. Piece, length (length-biased for the exits), direction.
    const double u = rng.uniform() * total;
    const int k = u < c[0] ? 0 : u < c[0] + c[1] ? 1 : 2;
    f.length = sample_length(spec.length, k == 0 ? 0 : 1, rng);
    f.angle = sample_orientation(spec.orientation, rng);
    const Vec2 d(std::cos(f.angle), std::sin(f.angle));
    // 2. A point of the fracture on B and its position s along the fracture
    // from the centre: the forward end anywhere in B, or the exit point
    // (kept with probability |cos t| or sin t) anywhere on its side.
    Vec2 on_box;
    double s = 0.5 * f.length;
    if (k == 0) {
      on_box = domain.lo + Vec2(rng.uniform() * size.x(), rng.uniform() * size.y());
    } else {
      if (rng.uniform() >= (k == 1 ? std::abs(d.x()) : d.y())) continue;
      on_box = k == 1 ? Vec2(d.x() >= 0 ? domain.hi.x() : domain.lo.x(),
                             domain.lo.y() + rng.uniform() * size.y())
                      : Vec2(domain.lo.x() + rng.uniform() * size.x(), domain.hi.y());
      s = (rng.uniform() - 0.5) * f.length;
    }
    f.centre = on_box - s * d;
    // 3. Aperture.
    f.aperture = sample_aperture(spec.aperture, f.length, rng);
    fractures.push_back(f);
  }
  return fractures;
}

}  // namespace

bool dfn_uses_strips(const DfnFamilySpec& spec, const Box& domain) {
  const std::array<double, 3> c = grown_weights(spec, domain);
  return c[2] > c[0] + c[1];
}

double expected_dfn_fractures(const DfnFamilySpec& spec, const Box& domain) {
  return dfn_p20(spec) * sum(dfn_uses_strips(spec, domain) ? strip_weights(spec, domain)
                                                           : grown_weights(spec, domain));
}

std::vector<DfnFracture> generate_dfn_family(const DfnFamilySpec& spec, const Box& domain,
                                             Rng& rng) {
  return dfn_uses_strips(spec, domain) ? draw_in_strip_window(spec, domain, rng)
                                       : draw_in_grown_window(spec, domain, rng);
}

}  // namespace fissure
