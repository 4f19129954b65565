#include "rockmass/fields/continuum_interface.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace fissure {

ContinuumInterfaceLoad& interface_load(std::vector<ContinuumInterfaceLoad>& all,
                                       const std::string& name) {
  if (ContinuumInterfaceLoad* x = find_interface(all, name)) return *x;
  all.push_back({});
  all.back().name = name;
  return all.back();
}

InterfacePlace locate_on_interface(const ContinuumInterface& i, const Vec2& x) {
  InterfacePlace best;
  for (std::size_t e = 0; e < i.edges.size(); ++e) {
    const Vec2 &a = i.nodes[i.edges[e][0]], &b = i.nodes[i.edges[e][1]];
    const Vec2 ab = b - a;
    const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d = (a + s * ab - x).norm();
    if (d < best.distance) best = {static_cast<int>(e), s, d};
  }
  return best;
}

std::array<double, 3> quadratic_weights(double s) {
  return {(1 - s) * (1 - 2 * s), s * (2 * s - 1), 4 * s * (1 - s)};
}

std::array<double, 2> linear_weights(double s) {
  return {1 - s, s};
}

Vec2 displacement_at(const ContinuumInterface& i, const InterfacePlace& at) {
  const auto [a, b] = i.edges[at.edge];
  const std::array<double, 3> n = quadratic_weights(at.s);
  return n[0] * i.displacement[a] + n[1] * i.displacement[b] +
         n[2] * i.midside_displacement[at.edge];
}

namespace {
double linear_at(const std::vector<double>& v, const ContinuumInterface& i,
                 const InterfacePlace& at, const char* what) {
  FISSURE_CHECK(v.size() == i.nodes.size(), std::logic_error,
                "interface '" << i.name << "' has " << v.size() << " " << what << " values for "
                              << i.nodes.size() << " nodes");
  const auto [a, b] = i.edges[at.edge];
  return (1 - at.s) * v[a] + at.s * v[b];
}
}  // namespace

double pressure_at(const ContinuumInterface& i, const InterfacePlace& at) {
  return linear_at(i.pressure, i, at, "pressure");
}

double temperature_at(const ContinuumInterface& i, const InterfacePlace& at) {
  return linear_at(i.temperature, i, at, "temperature");
}

double interface_tolerance(const ContinuumInterface& i) {
  if (i.nodes.empty()) return 1e-9;
  Vec2 lo = i.nodes[0], hi = i.nodes[0];
  for (const Vec2& p : i.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return std::max(1e-9, 1e-9 * (hi - lo).norm());
}

}  // namespace fissure
