// Process::exchanged_values and set_exchanged_values for a process whose
// exchanged values are the entries of some of its shared fields: `fields`
// declares them (its section's SectionReader::exchanges) and
// `for_each(state, visit)` visits every value as visit(k, double&) or
// visit(k, double), k the index of its field in `fields`.
#pragma once

#include <span>
#include <vector>

#include "core/scene/exchanged_field.h"
#include "core/state/rock_mass.h"

namespace fissure {

/// One exchanged field's values, as a pass left them.
struct ExchangedField {
  const ExchangedFieldKind* kind = nullptr;
  std::vector<double> values;
};

template <class ForEach>
std::vector<ExchangedField> gather_exchanged(const RockMass& state,
                                             std::span<const ExchangedFieldKind> fields,
                                             ForEach&& for_each) {
  std::vector<ExchangedField> gathered(fields.size());
  for (std::size_t k = 0; k < fields.size(); ++k) gathered[k].kind = &fields[k];
  for_each(state, [&](std::size_t k, double v) { gathered[k].values.push_back(v); });
  return gathered;
}

/// Writes `values` back in the same order. A field whose layout in the
/// state differs (it was made in the step, after the state the iteration
/// starts each pass from) is left as it is: the process makes it again when
/// it advances.
template <class ForEach>
void scatter_exchanged(RockMass& state, std::span<const ExchangedField> values,
                       ForEach&& for_each) {
  std::vector<std::size_t> count(values.size(), 0);
  for_each(state, [&](std::size_t k, double) { ++count[k]; });
  std::vector<std::size_t> next(values.size(), 0);
  for_each(state, [&](std::size_t k, double& v) {
    if (count[k] == values[k].values.size()) v = values[k].values[next[k]++];
  });
}

}  // namespace fissure
