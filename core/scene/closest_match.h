// "Did you mean ...?" for misspelt keys, names and units.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fissure {

/// Optimal-string-alignment distance: insertions, deletions, substitutions and
/// transpositions of adjacent characters each cost 1 ("denisty" -> "density"
/// is 1). Case-insensitive.
int edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` if it is within a small distance (1 for
/// words up to 4 characters, 2 up to 8, else 3); ties go to the first.
std::optional<std::string> closest_match(std::string_view word,
                                         std::span<const std::string_view> candidates);

}  // namespace fissure
