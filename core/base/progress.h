// Run progress: a one-line bar redrawn in place on a terminal (step, simulated
// time, wall time, ETA), plain log lines every 10 % otherwise.
#pragma once

#include <chrono>
#include <cstdio>

namespace fissure {

class Progress {
 public:
  /// `end_time` > 0; `interactive` = draw a bar (stderr is a terminal).
  Progress(double end_time, bool interactive, bool quiet);
  void update(long step, double t);
  /// Ends the bar line.
  void finish(long step, double t);
  double wall_seconds() const;

  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

 private:
  void draw(long step, double t, bool final);

  double end_time_;
  bool interactive_, quiet_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  int last_decile_ = -1;
};

}  // namespace fissure
