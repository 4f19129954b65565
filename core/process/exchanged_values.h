// Process::exchanged_values and set_exchanged_values for a process whose
// exchanged values are the entries of some of its shared fields, visited in
// one order by `for_each(state, visit)` (visit(double&) or visit(double)).
#pragma once

#include <span>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

template <class ForEach>
std::vector<double> gather_exchanged(const RockMass& state, ForEach&& for_each) {
  std::vector<double> values;
  for_each(state, [&](double v) { values.push_back(v); });
  return values;
}

/// Writes `values` back in the same order. Where the state's fields have
/// another layout (a field was made in the step, after the state the
/// iteration starts each pass from), they are left as they are: the process
/// makes them again when it advances.
template <class ForEach>
void scatter_exchanged(RockMass& state, std::span<const double> values, ForEach&& for_each) {
  std::size_t n = 0;
  for_each(state, [&](double) { ++n; });
  if (n != values.size()) return;
  std::size_t k = 0;
  for_each(state, [&](double& v) { v = values[k++]; });
}

}  // namespace fissure
