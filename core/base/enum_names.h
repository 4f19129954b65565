// One table of an enum's names in the scene and the output, read and
// written from the same rows (a key's reader offers the names, summary.json
// writes them back).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fissure {

template <class Enum>
struct EnumName {
  std::string_view name;
  Enum value;
};

/// The names of the rows, in order (the choices a reader offers).
template <class Enum, std::size_t N>
constexpr std::array<std::string_view, N> enum_names(const EnumName<Enum> (&table)[N]) {
  std::array<std::string_view, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = table[i].name;
  return names;
}

/// The name of `value`; a logic_error for a value without a row.
template <class Enum, std::size_t N>
constexpr std::string_view name_of(const EnumName<Enum> (&table)[N], Enum value) {
  for (const EnumName<Enum>& row : table)
    if (row.value == value) return row.name;
  throw std::logic_error("an enum value without a name");
}

/// The value named `name`; a logic_error for a name without a row (the
/// reader has checked it against enum_names).
template <class Enum, std::size_t N>
constexpr Enum value_of(const EnumName<Enum> (&table)[N], std::string_view name) {
  for (const EnumName<Enum>& row : table)
    if (row.name == name) return row.value;
  throw std::logic_error("no enum value named '" + std::string(name) + "'");
}

}  // namespace fissure
