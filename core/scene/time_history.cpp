#include "core/scene/time_history.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/scene/config_map.h"
#include "core/scene/config_node.h"
#include "core/scene/units.h"

namespace fissure {

double history_factor(const TimeHistory& h, double t) {
  if (h.empty()) return 1.0;
  if (t <= h.front().first) return h.front().second;
  if (t >= h.back().first) return h.back().second;
  const auto it =
      std::upper_bound(h.begin(), h.end(), t, [](double x, const auto& e) { return x < e.first; });
  const auto& [t1, f1] = *(it - 1);
  const auto& [t2, f2] = *it;
  return f1 + (f2 - f1) * (t - t1) / (t2 - t1);
}

void read_history(const ConfigNode& node, TimeHistory& history) {
  const auto items = node.list("pairs [t, factor] with increasing t", true);
  if (!items) return;
  const QuantityKind* kinds[] = {&quantity::time, &quantity::dimensionless};
  std::optional<double> previous;
  for (const ConfigNode& item : *items) {
    const auto pair = item.numbers(kinds, "[t, factor]");
    if (!pair) continue;
    if (previous && (*pair)[0] <= *previous)
      item.error(fmt::format("found t = {} s after t = {} s; expected strictly increasing times",
                             (*pair)[0], *previous));
    previous = (*pair)[0];
    history.emplace_back((*pair)[0], (*pair)[1]);
  }
}

namespace {

/// `decay: [[a, tau], ...]` with tau > 0.
void read_decay(const ConfigNode& node, std::vector<std::pair<double, double>>& out) {
  const auto items = node.list("pairs [a, tau]", true);
  if (!items) return;
  const QuantityKind* kinds[] = {&quantity::dimensionless, &quantity::time};
  for (const ConfigNode& item : *items) {
    const auto pair = item.numbers(kinds, "pairs [a, tau]");
    if (!pair) continue;
    if (!((*pair)[1] > 0))
      item.error(fmt::format("found tau = {} s; expected a decay time > 0", (*pair)[1]));
    out.emplace_back((*pair)[0], (*pair)[1]);
  }
}

}  // namespace

double TimeFactor::at(double t) const {
  if (decay.empty()) return history_factor(history, t);
  double f = 0;
  for (const auto& [a, tau] : decay) f += a * std::exp(-t / tau);
  return f;
}

void read_time_factor(ConfigMap& map, TimeFactor& factor) {
  std::optional<ConfigNode> history = map.optional("history");
  if (history) read_history(*history, factor.history);
  if (auto n = map.optional("decay")) {
    read_decay(*n, factor.decay);
    if (history) n->error_at_key("found both history and decay; expected one of them");
  }
}

}  // namespace fissure
