#include "core/geometry/lattice_seeds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/geometry/box_grid.h"
#include "core/geometry/polygon_locator.h"
#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

/// Levels are clamped to this range of halvings and doublings of the
/// spacing at the polygon's centre (a size function 2^30 times finer than
/// there is beyond any mesh).
constexpr int kMaxLevel = 30;

/// The triangular lattice of spacing s0 / 2^k (rows s sqrt(3) / 2 apart,
/// every other row shifted by s / 2), anchored at one origin for every k:
/// the lattice of level k + 1 holds all points of level k (the spacings
/// are exact powers of two apart), so that cells of neighbouring levels
/// join without near-duplicate points.
class LatticeFamily {
 public:
  LatticeFamily(const Vec2& origin, double s0) : origin_(origin), s0_(s0) {}
  double spacing(int k) const { return std::ldexp(s0_, -k); }
  /// The finest level whose spacing is at most kLatticeSpacing h.
  int level(double h) const {
    const double k = std::ceil(std::log2(s0_ / (kLatticeSpacing * h)) - 1e-9);
    return static_cast<int>(std::clamp(k, double(-kMaxLevel), double(kMaxLevel)));
  }
  /// Calls f(point) for the points of level k in the half-open box
  /// [lo, hi).
  template <class F>
  void for_each_point(int k, const Vec2& lo, const Vec2& hi, F&& f) const {
    const double s = spacing(k), dy = s * std::sqrt(3.0) / 2;
    for (long long j = static_cast<long long>(std::ceil((lo.y() - origin_.y()) / dy));; ++j) {
      const double y = origin_.y() + static_cast<double>(j) * dy;
      if (y >= hi.y()) break;
      if (y < lo.y()) continue;
      const double shift = (j & 1) ? s / 2 : 0;
      for (long long i = static_cast<long long>(std::ceil((lo.x() - origin_.x() - shift) / s));;
           ++i) {
        const double x = origin_.x() + shift + static_cast<double>(i) * s;
        if (x >= hi.x()) break;
        if (x >= lo.x()) f(Vec2(x, y));
      }
    }
  }

 private:
  Vec2 origin_;
  double s0_;
};

/// The constrained lines and points inside the region, for distance
/// queries: a grid of their segments (a point is a segment of length 0).
class Obstacles {
 public:
  explicit Obstacles(const MesherInput& input) {
    for (const std::vector<Vec2>& line : input.polylines)
      for (std::size_t i = 0; i + 1 < line.size(); ++i) add(line[i], line[i + 1]);
    for (const Vec2& p : input.points) add(p, p);
    if (!boxes_.empty()) grid_.build(boxes_);
  }
  /// Whether a segment or point lies within `distance` of p.
  bool near(const Vec2& p, double distance) const {
    if (boxes_.empty()) return false;
    Box query;
    query.extend(p - Vec2(distance, distance));
    query.extend(p + Vec2(distance, distance));
    bool found = false;
    grid_.for_each_overlapping(query, [&](int i) {
      if (!found) found = point_segment_distance(p, ends_[i][0], ends_[i][1]) < distance;
    });
    return found;
  }

 private:
  void add(const Vec2& a, const Vec2& b) {
    ends_.push_back({a, b});
    Box box;
    box.extend(a);
    box.extend(b);
    boxes_.push_back(box);
  }
  std::vector<std::array<Vec2, 2>> ends_;
  std::vector<Box> boxes_;
  BoxGrid grid_;
};

}  // namespace

std::vector<Vec2> lattice_seeds(const MesherInput& input, const SizeFunction& size) {
  if (input.loops.empty() || input.loops[0].size() < 3) return {};
  Polygon region(input.loops[0]);
  for (std::size_t l = 1; l < input.loops.size(); ++l) region.add_loop(input.loops[l]);
  const PolygonLocator locator(region);
  const Obstacles obstacles(input);
  const Box bounds = locator.bounds();
  if (bounds.empty()) return {};

  const double h_centre = size(0.5 * (bounds.lo + bounds.hi));
  if (!(h_centre > 0) || !std::isfinite(h_centre)) return {};
  const LatticeFamily lattice(bounds.lo, kLatticeSpacing * h_centre);

  std::vector<Vec2> seeds;
  // Keeps the points of level k in the cell [lo, hi) that are inside the
  // region and clear of its edges and obstacles. A cell whose disc (its
  // half diagonal and the margin around its centre) meets no edge is inside
  // or outside as a whole.
  auto emit = [&](int k, const Vec2& lo, const Vec2& hi) {
    const double margin = kLatticeMargin * lattice.spacing(k);
    const Vec2 centre = 0.5 * (lo + hi);
    const int whole = locator.locate(centre, 0.5 * (hi - lo).norm() + margin);
    if (whole < 0) return;
    lattice.for_each_point(k, lo, hi, [&](const Vec2& p) {
      if (whole == 0 && locator.locate(p, margin) <= 0) return;
      if (obstacles.near(p, margin)) return;
      seeds.push_back(p);
    });
  };
  // A cell of one level where h varies by less than a halving across it
  // (sampled at its corners and centre) or where it is a few spacings
  // across; else its four quarters.
  auto fill = [&](auto&& self, const Vec2& lo, const Vec2& hi) -> void {
    double h_min = std::numeric_limits<double>::infinity(), h_max = 0;
    for (const Vec2& p :
         {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y()), Vec2(0.5 * (lo + hi))}) {
      const double h = size(p);
      if (!(h > 0) || !std::isfinite(h)) return;  // no seeds where the size is not usable
      h_min = std::min(h_min, h);
      h_max = std::max(h_max, h);
    }
    const int k = lattice.level(h_min);
    if (lattice.level(h_max) != k && (hi - lo).maxCoeff() > 4 * lattice.spacing(k)) {
      const Vec2 mid = 0.5 * (lo + hi);
      self(self, lo, mid);
      self(self, Vec2(mid.x(), lo.y()), Vec2(hi.x(), mid.y()));
      self(self, Vec2(lo.x(), mid.y()), Vec2(mid.x(), hi.y()));
      self(self, mid, hi);
      return;
    }
    emit(k, lo, hi);
  };
  // Top cells of 8 spacings at the centre (about 75 lattice points each),
  // at most 256 across (a size function fine at the centre alone).
  const double cell = std::max(8 * lattice.spacing(0), bounds.size().maxCoeff() / 256);
  const int nx = static_cast<int>(std::ceil(bounds.size().x() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(bounds.size().y() / cell)) + 1;
  for (int cy = 0; cy < ny; ++cy)
    for (int cx = 0; cx < nx; ++cx) {
      const Vec2 lo = bounds.lo + cell * Vec2(cx, cy);
      fill(fill, lo, lo + Vec2(cell, cell));
    }
  return seeds;
}

}  // namespace fissure
