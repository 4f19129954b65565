#include "tests/support/newmark_sliding_block.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace fissure::testing {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

void require(bool condition, const std::string& what) {
  if (!condition) throw std::invalid_argument("tests/support/newmark_sliding_block: " + what);
}

void check_record(const BaseAcceleration& base) {
  require(base.ax.size() == base.t.size() && base.ay.size() == base.t.size(),
          "t, ax and ay of different lengths");
  for (std::size_t i = 0; i < base.t.size(); ++i) {
    require(std::isfinite(base.t[i]) && std::isfinite(base.ax[i]) && std::isfinite(base.ay[i]),
            "a sample that is not finite");
    require(i == 0 || base.t[i] >= base.t[i - 1], "decreasing sample times");
  }
}

Eigen::Vector2d sample(const BaseAcceleration& base, std::size_t i) {
  return {base.ax[i], base.ay[i]};
}

/// value + slope tau, tau from the start of a stretch.
struct Linear {
  double value, slope;
  double operator()(double tau) const { return value + slope * tau; }
};

/// The first tau in (0, limit] at which the rate a + b tau + c tau^2 / 2 (a >= 0, the rate
/// along the sliding direction) reaches 0; infinity if none.
double first_stop(double a, double b, double c, double limit) {
  double root = kInfinity;
  if (a == 0) {
    // Just started (b >= 0): it stops at -2 b / c if decelerating, at once if it cannot move.
    if (b > 0 && c < 0)
      root = -2 * b / c;
    else if (b <= 0 && c <= 0)
      root = 0;
  } else if (c == 0) {
    if (b < 0) root = -a / b;
  } else {
    // c/2 tau^2 + b tau + a = 0 without cancellation (Press et al., Numerical Recipes 5.6).
    const double discriminant = b * b - 2 * a * c;
    if (discriminant >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      for (const double r : {q / (c / 2), a / q})
        if (r > 0) root = std::min(root, r);
    }
  }
  return root <= limit ? root : kInfinity;
}

/// Newmark's block advanced through stretches over which D and N are linear in time.
class RigidPlasticBlock {
 public:
  explicit RigidPlasticBlock(double mu) : mu_(mu) {}

  double slip() const { return slip_; }
  double slip_rate() const { return rate_; }
  bool lifted_off() const { return lifted_off_; }

  /// Advances by h under D(tau), N(tau); returns the time advanced (less than h on lift-off).
  double advance(Linear driving, Linear normal, double h) {
    double tau = 0;
    // Within a stretch D and N are linear: a handful of starts and stops at most.
    for (int events = 0; tau < h; ++events) {
      if (events > 100) throw std::logic_error("newmark_sliding_block: no progress");
      const double d = driving(tau), n = normal(tau);
      if (n <= 0) return lift_off(tau);
      // Up to the end of the stretch or to N = 0.
      double span = h - tau;
      bool lifts = false;
      if (normal.slope < 0 && n + normal.slope * span <= 0) {
        span = std::min(span, -n / normal.slope);
        lifts = true;
      }
      if (direction_ == 0) {
        // Stuck: it starts when the excess of |D| over mu N turns positive (both are linear).
        double start = kInfinity;
        int start_direction = 0;
        for (const int sign : {1, -1}) {
          double excess = yield_excess(sign, d, n);
          const double excess_slope = yield_excess(sign, driving.slope, normal.slope);
          // Just stopped in this direction, so decelerating: a positive excess is rounding.
          if (sign == stopped_direction_) excess = std::min(excess, 0.0);
          const double at = excess > 0 ? 0 : excess_slope > 0 ? -excess / excess_slope : kInfinity;
          if (at < start) {
            start = at;
            start_direction = sign;
          }
        }
        if (start < span) {
          tau += start;
          direction_ = start_direction;
          stopped_direction_ = 0;
          continue;
        }
        tau = lifts ? tau + span : h;
        stopped_direction_ = 0;
        if (lifts) return lift_off(tau);
        continue;
      }
      // Sliding: s'' = D - sign mu N, linear, so s' is quadratic and s cubic in tau.
      const int sign = direction_;
      double r0 = sign * yield_excess(sign, d, n);
      const double r1 = sign * yield_excess(sign, driving.slope, normal.slope);
      // Started where the excess crossed 0: a wrong sign there is rounding.
      if (rate_ == 0 && sign * r0 < 0) r0 = 0;
      const double stop = first_stop(sign * rate_, sign * r0, sign * r1, span);
      const double step = std::min(stop, span);
      slip_ += step * (rate_ + step * (r0 / 2 + step * r1 / 6));
      rate_ += step * (r0 + step * r1 / 2);
      tau = step == span && !lifts ? h : tau + step;
      if (stop <= span || sign * rate_ <= 0) {
        rate_ = 0;
        direction_ = 0;
        stopped_direction_ = sign;
      } else if (lifts) {
        return lift_off(tau);
      }
    }
    return h;
  }

 private:
  /// sign D - mu N: sliding towards `sign` starts where this turns positive; times `sign` it is
  /// the sliding acceleration (one expression for both, so that the two agree to the bit).
  double yield_excess(int sign, double driving, double normal) const {
    return sign * driving - mu_ * normal;
  }

  double lift_off(double tau) {
    lifted_off_ = true;
    return tau;
  }

  double mu_;
  double slip_ = 0, rate_ = 0;
  int direction_ = 0;          // 0 stuck, +-1 sliding along +-tangent
  int stopped_direction_ = 0;  // the direction it just stopped in, at this instant
  bool lifted_off_ = false;
};

/// Steps of dt in `duration`, a last partial step counted unless it is below 1e-9 dt.
std::size_t steps_of(double duration, double dt) {
  return static_cast<std::size_t>(std::ceil(duration / dt - 1e-9));
}

/// Standard normals from mt19937_64, the same with every standard library: 53-bit uniforms from
/// the top bits and Marsaglia's polar form of Box-Muller (log and sqrt, no sin/cos).
class PortableNormal {
 public:
  explicit PortableNormal(std::uint64_t seed) : engine_(seed) {}

  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    for (;;) {
      const double u = 2 * uniform() - 1, v = 2 * uniform() - 1;
      const double r2 = u * u + v * v;
      if (r2 <= 0 || r2 >= 1) continue;
      const double factor = std::sqrt(-2 * std::log(r2) / r2);
      spare_ = v * factor;
      has_spare_ = true;
      return u * factor;
    }
  }

 private:
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

/// Three filters in series driven by the noise w held over each sample step: Kanai-Tajimi
/// x'' + 2 zg wg x' + wg^2 x = -w, whose absolute acceleration a1 = -(2 zg wg x' + wg^2 x) is
/// the ground's; Clough and Penzien's high pass y'' + 2 zf wf y' + wf^2 y = -a1, output y''
/// (Clough and Penzien 1975, Dynamics of Structures); a second-order Butterworth low pass
/// z'' + sqrt2 wc z' + wc^2 z = wc^2 y'' for the fall of recorded spectra above f_max (Hanks
/// 1982, BSSA 72), output z.
class GroundFilter {
 public:
  explicit GroundFilter(const AccelerogramShape& shape)
      : wg_(2 * kPi * shape.ground_frequency),
        zg_(shape.ground_damping),
        wf_(2 * kPi * shape.high_pass_frequency),
        zf_(shape.high_pass_damping),
        wc_(2 * kPi * shape.low_pass_frequency) {}

  /// The output now (0 at rest).
  double output() const { return wc_ > 0 ? state_[4] : high_passed(state_); }

  /// Classical RK4 over dt in substeps of at most 0.1 / w (the record is defined by this recipe,
  /// so its accuracy only needs to keep the spectrum's shape).
  void advance(double noise, double dt) {
    const double w = std::max({wg_, wf_, wc_});
    const int substeps = std::max(1, static_cast<int>(std::ceil(dt * w / 0.1)));
    const double h = dt / substeps;
    for (int i = 0; i < substeps; ++i) {
      const State k1 = derivative(state_, noise);
      const State k2 = derivative(add(state_, k1, h / 2), noise);
      const State k3 = derivative(add(state_, k2, h / 2), noise);
      const State k4 = derivative(add(state_, k3, h), noise);
      for (std::size_t j = 0; j < state_.size(); ++j)
        state_[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
  }

 private:
  using State = std::array<double, 6>;  // x, x', y, y', z, z'

  static State add(const State& s, const State& rate, double h) {
    State sum;
    for (std::size_t j = 0; j < s.size(); ++j) sum[j] = s[j] + h * rate[j];
    return sum;
  }

  double ground(const State& s) const { return -(2 * zg_ * wg_ * s[1] + wg_ * wg_ * s[0]); }

  double high_passed(const State& s) const {
    return -ground(s) - 2 * zf_ * wf_ * s[3] - wf_ * wf_ * s[2];
  }

  State derivative(const State& s, double noise) const {
    const double y2 = high_passed(s);
    const double z2 = wc_ * wc_ * (y2 - s[4]) - std::numbers::sqrt2 * wc_ * s[5];
    return {s[1], ground(s) - noise, s[3], y2, s[5], z2};
  }

  double wg_, zg_, wf_, zf_, wc_;
  State state_{};
};

/// Saragoni-Hart: (t/tp)^b exp(-b (t/tp - 1)) peaks at 1 at tp = peak_time T and is end_level
/// at T (Saragoni and Hart 1974 as in Boore 2003, PAGEOPH 160), tapered by a half cosine over the
/// last 5 % to 0.
double envelope(double t, double duration, const AccelerogramShape& shape) {
  if (t <= 0 || t >= duration) return 0;
  const double eps = shape.peak_time, eta = shape.end_level;
  const double b = -eps * std::log(eta) / (1 + eps * (std::log(eps) - 1));
  const double x = t / (eps * duration);
  const double window = std::pow(x, b) * std::exp(-b * (x - 1));
  const double taper_start = 0.95 * duration;
  if (t <= taper_start) return window;
  return window * 0.5 * (1 + std::cos(kPi * (t - taper_start) / (duration - taper_start)));
}

BaseAcceleration along(const std::vector<double>& t, const std::vector<double>& a,
                       const Eigen::Vector2d& direction) {
  require(direction.norm() > 0, "a zero direction");
  const Eigen::Vector2d unit = direction.normalized();
  BaseAcceleration base{t, a, a};
  for (std::size_t i = 0; i < a.size(); ++i) {
    base.ax[i] = a[i] * unit.x();
    base.ay[i] = a[i] * unit.y();
  }
  return base;
}

}  // namespace

Eigen::Vector2d BaseAcceleration::at(double time) const {
  if (t.empty() || time < t.front() || time > t.back()) return Eigen::Vector2d::Zero();
  const auto next = std::upper_bound(t.begin(), t.end(), time);
  const auto i = static_cast<std::size_t>(next - t.begin());
  if (i == t.size()) return sample(*this, i - 1);  // time == t.back()
  const double w = (time - t[i - 1]) / (t[i] - t[i - 1]);
  return (1 - w) * sample(*this, i - 1) + w * sample(*this, i);
}

SlidingPlane incline_rising_towards_x(double slope) {
  return {-Eigen::Vector2d(std::cos(slope), std::sin(slope)),
          Eigen::Vector2d(-std::sin(slope), std::cos(slope))};
}

SlidingBlockHistory newmark_sliding_block(const BaseAcceleration& base, const SlidingPlane& plane,
                                          double mu, const Eigen::Vector2d& gravity, double t_end,
                                          double dt_output) {
  check_record(base);
  const Eigen::Vector2d& tangent = plane.tangent;
  const Eigen::Vector2d& normal = plane.normal;
  require(std::abs(tangent.norm() - 1) < 1e-12 && std::abs(normal.norm() - 1) < 1e-12,
          "tangent and normal must be unit vectors");
  require(std::abs(tangent.dot(normal)) < 1e-12, "tangent and normal must be perpendicular");
  require(mu >= 0 && std::isfinite(mu), "mu must be >= 0");
  require(gravity.allFinite(), "gravity not finite");
  require(t_end >= 0 && dt_output > 0, "t_end must be >= 0 and dt_output > 0");

  SlidingBlockHistory history;
  RigidPlasticBlock block(mu);
  const auto record = [&](double time) {
    history.t.push_back(time);
    history.slip.push_back(block.slip());
    history.slip_rate.push_back(block.slip_rate());
  };
  const std::size_t outputs = steps_of(t_end, dt_output);
  const auto output_time = [&](std::size_t k) { return k < outputs ? k * dt_output : t_end; };
  const std::size_t samples = base.t.size();

  double time = 0;
  std::size_t next_output = 1;
  // The first sample after `time`: the stretch is [t_{i-1}, t_i] of the record, or before or
  // after it (no acceleration).
  auto next_sample = static_cast<std::size_t>(std::upper_bound(base.t.begin(), base.t.end(), time) -
                                              base.t.begin());
  record(0);
  while (next_output <= outputs) {
    const double output_at = output_time(next_output);
    const bool inside = next_sample > 0 && next_sample < samples;
    const double stretch_end =
        next_sample < samples ? std::min(output_at, base.t[next_sample]) : output_at;
    Eigen::Vector2d a = Eigen::Vector2d::Zero(), a_slope = Eigen::Vector2d::Zero();
    if (inside) {
      const std::size_t i = next_sample;
      a_slope = (sample(base, i) - sample(base, i - 1)) / (base.t[i] - base.t[i - 1]);
      a = sample(base, i - 1) + (time - base.t[i - 1]) * a_slope;
    }
    // The block feels g - a_b in the base's frame.
    const Linear driving{(gravity - a).dot(tangent), -a_slope.dot(tangent)};
    const Linear pressing{-(gravity - a).dot(normal), a_slope.dot(normal)};
    const double h = stretch_end - time;
    const double advanced = block.advance(driving, pressing, h);
    if (block.lifted_off()) {
      history.lifted_off = true;
      if (time + advanced > history.t.back()) record(time + advanced);
      return history;
    }
    time = stretch_end;
    while (next_sample < samples && base.t[next_sample] <= time) ++next_sample;
    if (time == output_at) {
      record(time);
      ++next_output;
    }
  }
  return history;
}

BaseAcceleration synthetic_accelerogram(double duration, double dt, double pga, std::uint64_t seed,
                                        const Eigen::Vector2d& direction,
                                        const AccelerogramShape& shape) {
  require(duration > 0 && dt > 0 && pga >= 0, "duration, dt must be > 0 and pga >= 0");
  require(shape.ground_frequency > 0 && shape.high_pass_frequency >= 0 &&
              shape.ground_damping > 0 && shape.high_pass_damping > 0 &&
              shape.low_pass_frequency >= 0,
          "bad filter");
  require(shape.peak_time > 0 && shape.peak_time < 1 && shape.end_level > 0 && shape.end_level < 1,
          "bad envelope");
  const std::size_t steps = steps_of(duration, dt);
  const double end = steps * dt;
  PortableNormal noise(seed);
  GroundFilter filter(shape);
  std::vector<double> t(steps + 1), a(steps + 1);
  std::size_t peak_index = 0;
  for (std::size_t k = 0; k <= steps; ++k) {
    t[k] = k * dt;
    a[k] = envelope(t[k], end, shape) * filter.output();
    if (std::abs(a[k]) > std::abs(a[peak_index])) peak_index = k;
    filter.advance(noise(), dt);
  }
  const double peak = std::abs(a[peak_index]);
  for (double& value : a) value = peak > 0 ? value * (pga / peak) : 0;
  if (peak > 0) a[peak_index] = std::copysign(pga, a[peak_index]);  // exact despite rounding
  return along(t, a, direction);
}

BaseAcceleration sinusoidal_base(double amplitude, double frequency, double duration, double dt,
                                 const Eigen::Vector2d& direction) {
  require(duration > 0 && dt > 0, "duration and dt must be > 0");
  const std::size_t steps = steps_of(duration, dt);
  std::vector<double> t(steps + 1), a(steps + 1);
  for (std::size_t k = 0; k <= steps; ++k) {
    t[k] = k * dt;
    a[k] = amplitude * std::sin(2 * kPi * frequency * t[k]);
  }
  return along(t, a, direction);
}

}  // namespace fissure::testing
