// Piecewise-linear factors of time, as the scene gives them (`history:
// [[t, factor], ...]` of point loads, flow conditions and wells, heat sources
// and thermal conditions): reading them, with located errors, and
// evaluating them.
#pragma once

#include <utility>
#include <vector>

namespace fissure {

class ConfigNode;

/// Points (t_i, f_i) with strictly increasing t_i.
using TimeHistory = std::vector<std::pair<double, double>>;

/// f(t): linear between the points, held at the first and last value
/// outside them; 1 without points.
double history_factor(const TimeHistory& history, double t);

/// Reads `[[t, factor], ...]` (t a time with units, factor a number) into
/// `history`; errors (located at the offending pair) for a pair that is not
/// two numbers and for times that do not increase strictly.
void read_history(const ConfigNode& node, TimeHistory& history);

}  // namespace fissure
