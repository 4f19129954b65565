// Factors of time, as the scene gives them: piecewise-linear (`history:
// [[t, factor], ...]` of point loads, flow conditions and wells, heat
// sources and the thermal and continuum conditions) or a sum of decaying
// exponentials (`decay: [[a, tau], ...]`, the decay heat of spent fuel, in
// the thermal and continuum sections alike): reading them, with located
// errors, and evaluating them.
#pragma once

#include <utility>
#include <vector>

namespace fissure {

class ConfigNode;
class ConfigMap;

/// Points (t_i, f_i) with strictly increasing t_i.
using TimeHistory = std::vector<std::pair<double, double>>;

/// f(t): linear between the points, held at the first and last value
/// outside them; 1 without points.
double history_factor(const TimeHistory& history, double t);

/// Reads `[[t, factor], ...]` (t a time with units, factor a number) into
/// `history`; errors (located at the offending pair) for a pair that is not
/// two numbers and for times that do not increase strictly.
void read_history(const ConfigNode& node, TimeHistory& history);

/// A factor of time: the piecewise-linear `history`, the sum of
/// exponentials of `decay`, or 1 with neither.
struct TimeFactor {
  TimeHistory history;
  std::vector<std::pair<double, double>> decay;  ///< (a_i, tau_i): sum a_i exp(-t / tau_i)
  double at(double t) const;
};

/// Reads the keys `history` and `decay` (at most one of them) of `map`, an
/// entry whose table lists both; `decay` is a non-empty list of [a, tau]
/// with tau > 0 (a time).
void read_time_factor(ConfigMap& map, TimeFactor& factor);

}  // namespace fissure
