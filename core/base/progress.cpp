#include "core/base/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace fissure {

Progress::Progress(double end_time, bool interactive, bool quiet)
    : end_time_(end_time),
      interactive_(interactive),
      quiet_(quiet),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

bool Progress::stderr_is_terminal() { return isatty(fileno(stderr)) != 0; }

double Progress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(long step, double t) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (interactive_) {
    if (now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    draw(step, t, false);
    return;
  }
  const int decile = static_cast<int>(std::floor(10 * t / end_time_));
  if (decile > last_decile_) {
    last_decile_ = decile;
    draw(step, t, false);
  }
}

void Progress::finish(long step, double t) {
  if (quiet_) return;
  draw(step, t, true);
}

void Progress::draw(long step, double t, bool final) {
  const double fraction = std::clamp(t / end_time_, 0.0, 1.0);
  const double wall = wall_seconds();
  const double eta = fraction > 1e-6 ? wall * (1 - fraction) / fraction : 0;
  if (interactive_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    char bar[width + 1];
    for (int i = 0; i < width; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
    bar[width] = '\0';
    std::fprintf(stderr, "\r[%s] %5.1f%%  step %ld  t = %.4g s  wall %.1f s  ETA %.1f s   ", bar,
                 100 * fraction, step, t, wall, eta);
    if (final) std::fprintf(stderr, "\n");
  } else {
    std::fprintf(stderr, "progress: %5.1f%%  step %ld  t = %.6g s  wall %.2f s  ETA %.1f s\n",
                 100 * fraction, step, t, wall, eta);
  }
  std::fflush(stderr);
}

}  // namespace fissure
