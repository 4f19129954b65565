#include "rockmass/joint_sets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fissure {

namespace {

/// Parameter range [t0, t1] of the line p + t d inside box b (Liang-Barsky);
/// empty (t0 > t1) when the line misses it.
std::pair<double, double> clip_line(const Vec2& p, const Vec2& d, const Box& b) {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-300) {
      if (p[axis] < b.lo[axis] || p[axis] > b.hi[axis]) return {1, 0};
      continue;
    }
    double a = (b.lo[axis] - p[axis]) / d[axis];
    double c = (b.hi[axis] - p[axis]) / d[axis];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
  }
  return {t0, t1};
}

Box grown(const Box& b) {
  const double margin = 0.01 * b.size().maxCoeff();
  Box g = b;
  g.lo -= Vec2(margin, margin);
  g.hi += Vec2(margin, margin);
  return g;
}

/// Range of (p - o) . axis over the corners of b.
std::pair<double, double> project(const Box& b, const Vec2& o, const Vec2& axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : {b.lo.x(), b.hi.x()})
    for (double y : {b.lo.y(), b.hi.y()}) {
      const double c = (Vec2(x, y) - o).dot(axis);
      lo = std::min(lo, c);
      hi = std::max(hi, c);
    }
  return {lo, hi};
}

/// (cos a, sin a), exact for multiples of 90 degrees (a dip of 90 gives
/// truly vertical traces, not ones tilted by cos(pi/2) = 6e-17).
Vec2 direction(double a) {
  const double quarter = a / (0.5 * 3.14159265358979323846);
  const double k = std::round(quarter);
  if (std::abs(quarter - k) < 1e-12) {
    switch (((static_cast<long>(k) % 4) + 4) % 4) {
      case 0:
        return Vec2(1, 0);
      case 1:
        return Vec2(0, 1);
      case 2:
        return Vec2(-1, 0);
      default:
        return Vec2(0, -1);
    }
  }
  return Vec2(std::cos(a), std::sin(a));
}

}  // namespace

double joint_set_p21(const JointSetSpec& spec) {
  const double persistence =
      spec.trace_length ? *spec.trace_length / (*spec.trace_length + spec.bridge_length) : 1.0;
  return persistence / spec.spacing;
}

double expected_joint_traces(const JointSetSpec& spec, const Box& domain) {
  const Box box = grown(domain);
  const double diagonal = box.size().norm();
  const double lines = diagonal / (spec.spacing - spec.spacing_spread) + 2;
  const double per_line =
      spec.trace_length ? diagonal / (*spec.trace_length + spec.bridge_length) + 2 : 1;
  return lines * per_line;
}

void generate_joint_set(const JointSetSpec& spec, int set, const Box& domain, Rng& rng,
                        std::vector<FractureTrace>& traces) {
  const Box box = grown(domain);
  const Vec2 d = direction(spec.dip);
  const Vec2 n = perp(d);
  const Vec2 o = domain.lo;
  const auto [c_lo, c_hi] = project(box, o, n);

  // 1. Line offsets along n: c_0 = phase s, then spacing by spacing both ways.
  // Without spread, c_k = (phase + k) s exactly (no accumulated rounding).
  auto next_spacing = [&]() {
    return spec.spacing_spread > 0 ? spec.spacing + spec.spacing_spread * (2 * rng.uniform() - 1)
                                   : spec.spacing;
  };
  std::vector<std::pair<long, double>> lines;  // (k, c_k)
  const double c0 = spec.phase * spec.spacing;
  double c = c0;
  for (long k = 0; c <= c_hi; ++k) {
    if (c >= c_lo) lines.emplace_back(k, c);
    c = spec.spacing_spread > 0 ? c + next_spacing() : (spec.phase + (k + 1)) * spec.spacing;
  }
  c = c0;
  for (long k = -1;; --k) {
    c = spec.spacing_spread > 0 ? c - next_spacing() : (spec.phase + k) * spec.spacing;
    if (c < c_lo) break;
    if (c <= c_hi) lines.emplace_back(k, c);
  }
  std::sort(lines.begin(), lines.end());

  // 2. Joints along each line.
  const double period = spec.trace_length ? *spec.trace_length + spec.bridge_length : 0;
  for (const auto& [k, ck] : lines) {
    const Vec2 base = o + ck * n;
    const auto [t0, t1] = clip_line(base, d, box);
    if (!(t0 < t1)) continue;
    auto add = [&](double a, double b) {
      traces.push_back(FractureTrace{base + a * d, base + b * d, set, spec.joint, spec.aperture});
    };
    if (!spec.trace_length) {
      add(t0, t1);
      continue;
    }
    double shift = 0;
    if (spec.stagger) {
      const double f = *spec.stagger * static_cast<double>(k);
      shift = (f - std::floor(f)) * period;
    } else {
      shift = rng.uniform() * period;
    }
    const long m0 = static_cast<long>(std::floor((t0 - shift - *spec.trace_length) / period));
    const long m1 = static_cast<long>(std::ceil((t1 - shift) / period));
    for (long m = m0; m <= m1; ++m) {
      const double a = std::max(t0, shift + m * period);
      const double b = std::min(t1, shift + m * period + *spec.trace_length);
      if (b > a) add(a, b);
    }
  }
}

}  // namespace fissure
