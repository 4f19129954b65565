// Chooses between two ways of doing the same job by their measured cost:
// each call goes to the one with the lower running mean (the last
// measurement weighs half), an untried one is tried at once, and every
// `probe_every`-th call goes to the other one so that its estimate follows a
// changing workload. Used where neither alternative wins everywhere (linear
// solvers whose cost depends on the state of the contacts).
#pragma once

namespace fissure {

class CheaperOfTwo {
 public:
  explicit CheaperOfTwo(long probe_every) : probe_every_(probe_every) {}

  /// 0 or 1: the alternative to run next.
  int pick() {
    const int cheaper = cost_[1] < cost_[0] ? 1 : 0;
    return ++calls_ % probe_every_ == 0 ? 1 - cheaper : cheaper;
  }

  /// Running mean cost (seconds) of an alternative; 0 while untried.
  double cost(int which) const { return cost_[which]; }

  /// The cost (seconds) the alternative just took.
  void record(int which, double seconds) {
    cost_[which] = cost_[which] == 0 ? seconds : 0.5 * (cost_[which] + seconds);
  }

 private:
  long probe_every_;
  long calls_ = 0;
  double cost_[2] = {0, 0};  ///< running mean seconds; 0 = not tried yet
};

}  // namespace fissure
