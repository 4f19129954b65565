// Internal to rockmass/joints: the checks of a law's constructor. A law
// built in code with a value out of range is a programming error (a scene's
// values are checked, with their file and line, by read_joint_law.cpp).
#pragma once

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fissure::joints {

inline void require(bool ok, const char* law, const char* what, const char* expected,
                    double value) {
  if (!ok)
    throw std::invalid_argument(std::string(law) + ": " + what + " " + std::to_string(value) +
                                "; expected " + expected);
}
inline void require_positive(const char* law, const char* what, double value) {
  require(std::isfinite(value) && value > 0, law, what, "> 0", value);
}
inline void require_non_negative(const char* law, const char* what, double value) {
  require(std::isfinite(value) && value >= 0, law, what, ">= 0", value);
}
/// An angle in [0, 90) degrees, in radians.
inline void require_acute(const char* law, const char* what, double value) {
  require(value >= 0 && value < std::numbers::pi / 2, law, what, "in [0, 90) degrees", value);
}

}  // namespace fissure::joints
