#include "rockmass/fields/continuum_interface.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

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

std::string tied_before_continuum(std::string_view process, std::string_view what) {
  return fmt::format(
      "coupling.order: found the {} before the process that publishes the continuum interfaces "
      "{}; expected that process first, so that it is tied to them from the start",
      process, what);
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

namespace {

/// The part of the segment [a, b] along the edge [p, q]: its ends'
/// parameters on both, or nothing (not on the edge's line, or overlapping it
/// over no length).
std::optional<SegmentPiece> overlap(const Vec2& a, const Vec2& b, const Vec2& p, const Vec2& q,
                                    double tolerance) {
  const Vec2 pq = q - p;
  const double l2 = pq.squaredNorm();
  auto off_line = [&](const Vec2& x) {
    return std::abs(pq.x() * (x.y() - p.y()) - pq.y() * (x.x() - p.x())) / std::sqrt(l2);
  };
  if (off_line(a) > tolerance || off_line(b) > tolerance) return std::nullopt;
  const double sa = (a - p).dot(pq) / l2, sb = (b - p).dot(pq) / l2;
  const double s0 = std::max(0.0, std::min(sa, sb)), s1 = std::min(1.0, std::max(sa, sb));
  if ((s1 - s0) * std::sqrt(l2) <= tolerance) return std::nullopt;
  // The same ends on the segment, t = (s - sa) / (sb - sa).
  return SegmentPiece{-1, s0, s1, (s0 - sa) / (sb - sa), (s1 - sa) / (sb - sa)};
}

}  // namespace

std::vector<SegmentPiece> pieces_along(const ContinuumInterface& i, const Vec2& a, const Vec2& b) {
  const double tolerance = interface_tolerance(i);
  std::vector<SegmentPiece> pieces;
  double covered = 0;
  for (std::size_t e = 0; e < i.edges.size(); ++e)
    if (auto piece = overlap(a, b, i.nodes[i.edges[e][0]], i.nodes[i.edges[e][1]], tolerance)) {
      piece->edge = static_cast<int>(e);
      covered += std::abs(piece->t1 - piece->t0);
      pieces.push_back(*piece);
    }
  if (pieces.empty() || std::abs(covered - 1) * (b - a).norm() > 1e3 * tolerance) return {};
  return pieces;
}

}  // namespace fissure
