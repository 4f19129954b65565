#include "rockmass/block_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rockmass/dfn_generator.h"
#include "rockmass/distributions.h"
#include "rockmass/joint_sets.h"

namespace fissure {

namespace {

constexpr int kBins = 360;
constexpr double kPi = 3.14159265358979323846;

/// A line process: length per area and the distribution of its directions.
struct Source {
  double p21 = 0;
  std::vector<double> weights;  ///< kBins direction bins over [0, pi)
};

std::vector<double> single_direction(double angle) {
  std::vector<double> w(kBins, 0.0);
  double a = std::fmod(angle, kPi);
  if (a < 0) a += kPi;
  w[std::min(kBins - 1, static_cast<int>(a / kPi * kBins))] = 1;
  return w;
}

/// E|sin(theta_a - theta_b)| over the two direction distributions.
double mean_abs_sine(const std::vector<double>& a, const std::vector<double>& b,
                     const std::vector<double>& sine_of_bin_difference) {
  double s = 0;
  for (int i = 0; i < kBins; ++i) {
    if (a[i] == 0) continue;
    for (int j = 0; j < kBins; ++j)
      if (b[j] != 0) s += a[i] * b[j] * sine_of_bin_difference[(i - j + kBins) % kBins];
  }
  return s;
}

/// Expected crossings per unit area of the line processes: each pair once, a
/// process with itself half (see the header).
double crossing_density(const std::vector<Source>& sources) {
  std::vector<double> sine(kBins);
  for (int k = 0; k < kBins; ++k) sine[k] = std::abs(std::sin(k * kPi / kBins));
  double density = 0;
  for (size_t a = 0; a < sources.size(); ++a)
    for (size_t b = a; b < sources.size(); ++b)
      density += (a == b ? 0.5 : 1.0) * sources[a].p21 * sources[b].p21 *
                 mean_abs_sine(sources[a].weights, sources[b].weights, sine);
  return density;
}

Source dfn_source(const DfnFamilySpec& f) {
  return Source{dfn_p20(f) * length_moment(f.length, 1), orientation_weights(f.orientation, kBins)};
}

}  // namespace

RockMassEstimate estimate_rock_mass(const RockMassSpec& spec) {
  RockMassEstimate e;
  Box box;
  for (const Vec2& p : spec.domain) box.extend(p);
  const double area = std::abs(signed_area(spec.domain));
  if (box.empty() || area <= 0) return e;

  std::vector<Source> sources;
  for (const JointSetSpec& s : spec.joint_sets) {
    e.fractures += expected_joint_traces(s, box);
    sources.push_back(Source{joint_set_p21(s), single_direction(s.dip)});
  }
  for (const DfnFamilySpec& f : spec.dfn) {
    e.fractures += expected_dfn_fractures(f, box);
    sources.push_back(dfn_source(f));
  }
  if (!spec.fractures.empty()) {
    Source explicit_fractures;
    explicit_fractures.weights.assign(kBins, 0.0);
    double total = 0;
    for (const FractureSpec& f : spec.fractures) {
      const Vec2 d = f.to - f.from;
      const double l = d.norm();
      const std::vector<double> w = single_direction(std::atan2(d.y(), d.x()));
      for (int i = 0; i < kBins; ++i) explicit_fractures.weights[i] += l * w[i];
      total += l;
    }
    for (double& w : explicit_fractures.weights) w /= total;
    explicit_fractures.p21 = total / area;
    e.fractures += static_cast<double>(spec.fractures.size());
    sources.push_back(std::move(explicit_fractures));
  }

  e.intersections = area * crossing_density(sources);
  e.blocks = 1 + e.intersections + static_cast<double>(spec.excavations.size());
  return e;
}

double dfn_crossing_density(const std::vector<DfnFamilySpec>& families) {
  std::vector<Source> sources;
  for (const DfnFamilySpec& f : families) sources.push_back(dfn_source(f));
  return crossing_density(sources);
}

}  // namespace fissure
