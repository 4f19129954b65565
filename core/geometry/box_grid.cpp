#include "core/geometry/box_grid.h"

#include <algorithm>
#include <cmath>

namespace fissure {

void BoxGrid::build(std::span<const Box> boxes) {
  boxes_ = boxes;
  nx_ = ny_ = 0;
  start_.clear();
  entries_.clear();
  if (boxes.empty()) return;

  Box all;
  std::vector<double> extents;
  extents.reserve(boxes.size());
  for (const Box& b : boxes) {
    all.extend(b);
    extents.push_back(std::max(b.size().x(), b.size().y()));
  }
  auto mid = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
  std::nth_element(extents.begin(), mid, extents.end());
  const Vec2 span = all.size();
  const double n = static_cast<double>(boxes.size());
  const double min_cell = std::sqrt(std::max(span.x() * span.y(), 1e-300) / (4.0 * n));
  // The area bound alone does not limit the cell count when the overall extent
  // is thin or degenerate (all boxes on one line: 1e12 cells); bounding the
  // cells per row and column by 4N keeps nx * ny <= ~12 N + 4.
  const double min_row_cell = std::max(span.x(), span.y()) / (4.0 * n);
  cell_ = std::max({*mid, min_cell, min_row_cell, 1e-300});
  origin_ = all.lo;
  // Non-finite extents (infinite coordinates) fall back to a single cell.
  auto n_cells = [&](double extent) {
    const double c = std::ceil(extent / cell_);
    return c >= 0 && c <= 4 * n + 2 ? static_cast<int>(c) + 1 : 1;
  };
  nx_ = n_cells(span.x());
  ny_ = n_cells(span.y());

  // Two passes: count, then fill (CSR).
  start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (const Box& b : boxes)
    for (int cy = cell_y(b.lo.y()); cy <= cell_y(b.hi.y()); ++cy)
      for (int cx = cell_x(b.lo.x()); cx <= cell_x(b.hi.x()); ++cx) ++start_[cy * nx_ + cx + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  entries_.resize(start_.back());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    const Box& b = boxes[i];
    for (int cy = cell_y(b.lo.y()); cy <= cell_y(b.hi.y()); ++cy)
      for (int cx = cell_x(b.lo.x()); cx <= cell_x(b.hi.x()); ++cx)
        entries_[fill[cy * nx_ + cx]++] = i;
  }
}

}  // namespace fissure
