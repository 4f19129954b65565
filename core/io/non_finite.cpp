#include "core/io/non_finite.h"

#include <cmath>

#include <fmt/format.h>

namespace fissure {

namespace {

template <class Vector>
bool finite(const Vector& v) {
  return v.allFinite();
}

}  // namespace

std::string non_finite_block(const RockMass& state) {
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    const Block& block = state.blocks[b];
    const char* what = nullptr;
    if (!finite(block.velocity))
      what = "velocity";
    else if (!finite(block.stress))
      what = "stress";
    else if (!finite(block.strain))
      what = "strain";
    else if (!std::isfinite(block.rotation))
      what = "rotation";
    else
      for (const Vec2& v : block.polygon.vertices)
        if (!finite(v)) what = "vertex coordinates";
    if (what) return fmt::format("block '{}' ({}) has a non-finite {}", block.name, b, what);
  }
  return {};
}

std::string non_finite_monitor(const RockMass& state, const MonitorLayout& layout,
                               const std::vector<Monitor>& monitors) {
  const std::vector<MonitorLayout::Column>& columns = layout.columns();
  const int n = std::min(static_cast<int>(monitors.size()), static_cast<int>(state.points.size()));
  for (int m = 0; m < n && !columns.empty(); ++m) {
    const std::vector<double> values = layout.values(state, m);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (std::isfinite(values[c])) continue;
      const MonitorSource& source = layout.source(columns[c].source);
      if (std::isnan(values[c]) && !source.why_missing(state, m, columns[c].name).empty())
        continue;  // missing, and said why (an empty cell)
      return fmt::format("monitor '{}': column {}.{} = {}", monitors[m].name, monitors[m].name,
                         columns[c].name, values[c]);
    }
  }
  return {};
}

}  // namespace fissure
