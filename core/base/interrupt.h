// SIGINT and SIGTERM as a request to stop (issue 22, item 6): while an
// InterruptGuard lives, the first such signal only sets a flag, which the
// time loop reads after each step to write a checkpoint and stop cleanly;
// a second one ends the program at once (the default action), so that a
// user whose run does not react can still stop it.
#pragma once

namespace fissure {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received (SIGINT or SIGTERM), or 0.
  static int signal();
  /// "SIGINT", "SIGTERM".
  static const char* name(int signal);
};

}  // namespace fissure
