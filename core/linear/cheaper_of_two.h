// Chooses between two ways of doing the same job by their cost (a model
// cost from operation counts where runs must be reproducible):
// each call goes to the one with the lower running mean (the last
// measurement weighs half), an untried one is tried at once, and the other
// one is probed so that its estimate follows a changing workload: after
// `probe_every` calls times the ratio of the two means (at most
// kMaxStretch times), so that an alternative that costs twice as much is
// probed half as often and the probes cost a bounded share of the work.
// (Static 1,000-brick wall from rest: losing Krylov probes 21 -> 9 of 155
// solves, docs/performance-history.md.) Used where neither alternative wins
// everywhere (linear solvers whose cost depends on the state of the
// system).
#pragma once

#include <algorithm>

namespace fissure {

class CheaperOfTwo {
 public:
  explicit CheaperOfTwo(long probe_every) : probe_every_(probe_every) {}

  /// 0 or 1: the alternative to run next.
  int pick() {
    const int cheaper = cost_[1] < cost_[0] ? 1 : 0;
    const double ratio = cost_[cheaper] > 0 ? cost_[1 - cheaper] / cost_[cheaper] : 1;
    const double interval = probe_every_ * std::clamp(ratio, 1.0, kMaxStretch);
    if (++since_probe_ < interval) return cheaper;
    since_probe_ = 0;
    return 1 - cheaper;
  }

  /// Running mean cost of an alternative; 0 while untried.
  double cost(int which) const { return cost_[which]; }

  /// The cost the alternative just took.
  void record(int which, double cost) {
    cost_[which] = cost_[which] == 0 ? cost : 0.5 * (cost_[which] + cost);
  }

  /// Its state (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("since_probe", self.since_probe_);
    a("cost_0", self.cost_[0]);
    a("cost_1", self.cost_[1]);
  }

 private:
  static constexpr double kMaxStretch = 4;
  long probe_every_;
  long since_probe_ = 0;     ///< calls since the last probe
  double cost_[2] = {0, 0};  ///< running means; 0 = not tried yet
};

}  // namespace fissure
