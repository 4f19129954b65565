// Uniform-grid broad phase over axis-aligned boxes: reports every pair of
// overlapping boxes once, in O(N + pairs) for boxes of similar size (no
// all-pairs loop). Storage is compressed (CSR) so that the cell lists are
// contiguous. A pair is reported only from the cell that holds the lower-left
// corner of the two boxes' intersection, which removes duplicates without a
// hash set.
#pragma once

#include <span>
#include <type_traits>
#include <vector>

#include "core/geometry/polygon.h"

namespace fissure {

class BoxGrid {
 public:
  /// Index `boxes`. The cell size is the median box extent, enlarged where
  /// needed so that the grid has at most ~4 cells per box.
  void build(std::span<const Box> boxes);

  /// Calls f(i, j), i < j, once for every pair of overlapping boxes. An f
  /// that returns bool stops the enumeration by returning true.
  template <class F>
  void for_each_pair(F&& f) const;

  /// Calls f(i) once for every indexed box that overlaps `query`.
  template <class F>
  void for_each_overlapping(const Box& query, F&& f) const;

  double cell_size() const { return cell_; }

 private:
  // Clamped in floating point before the conversion: a coordinate far outside
  // the grid (or a query box such as [-1e300, 1e300]) would overflow the int
  // conversion, which is undefined behaviour. NaN maps to cell 0. Inline: the
  // queries call them for every candidate box.
  static int clamped_cell(double t, int n) {
    if (!(t > 0)) return 0;
    if (t >= n - 1) return n - 1;
    return static_cast<int>(t);
  }
  int cell_x(double x) const { return clamped_cell((x - origin_.x()) / cell_, nx_); }
  int cell_y(double y) const { return clamped_cell((y - origin_.y()) / cell_, ny_); }

  std::span<const Box> boxes_;
  Vec2 origin_ = Vec2::Zero();
  double cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_;    ///< CSR offsets, size nx*ny + 1
  std::vector<int> entries_;  ///< box indices per cell
};

template <class F>
void BoxGrid::for_each_pair(F&& f) const {
  for (int cy = 0; cy < ny_; ++cy) {
    for (int cx = 0; cx < nx_; ++cx) {
      const int c = cy * nx_ + cx;
      for (int a = start_[c]; a < start_[c + 1]; ++a) {
        const int i = entries_[a];
        const Box& bi = boxes_[i];
        for (int b = a + 1; b < start_[c + 1]; ++b) {
          const int j = entries_[b];
          const Box& bj = boxes_[j];
          if (!bi.overlaps(bj)) continue;
          // Report only from the cell owning the intersection's lower-left corner.
          const double lx = std::max(bi.lo.x(), bj.lo.x());
          const double ly = std::max(bi.lo.y(), bj.lo.y());
          if (cell_x(lx) != cx || cell_y(ly) != cy) continue;
          if constexpr (std::is_same_v<std::invoke_result_t<F, int, int>, bool>) {
            if (i < j ? f(i, j) : f(j, i)) return;
          } else if (i < j) {
            f(i, j);
          } else {
            f(j, i);
          }
        }
      }
    }
  }
}

template <class F>
void BoxGrid::for_each_overlapping(const Box& q, F&& f) const {
  if (nx_ == 0) return;
  const int x0 = cell_x(q.lo.x()), x1 = cell_x(q.hi.x());
  const int y0 = cell_y(q.lo.y()), y1 = cell_y(q.hi.y());
  for (int cy = y0; cy <= y1; ++cy) {
    for (int cx = x0; cx <= x1; ++cx) {
      const int c = cy * nx_ + cx;
      for (int a = start_[c]; a < start_[c + 1]; ++a) {
        const int i = entries_[a];
        const Box& b = boxes_[i];
        if (!b.overlaps(q)) continue;
        // Report once: from the cell owning the lower-left corner of the overlap.
        if (cell_x(std::max(b.lo.x(), q.lo.x())) != cx ||
            cell_y(std::max(b.lo.y(), q.lo.y())) != cy)
          continue;
        f(i);
      }
    }
  }
}

}  // namespace fissure
