#include "core/base/interrupt.h"

#include <csignal>

namespace fissure {

namespace {

volatile std::sig_atomic_t received = 0;
struct sigaction previous_int {
}, previous_term{};

extern "C" void on_signal(int s) {
  if (received != 0) {  // the second one: the default action
    std::signal(s, SIG_DFL);
    std::raise(s);
    return;
  }
  received = s;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  received = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int InterruptGuard::signal() {
  return received;
}

const char* InterruptGuard::name(int s) {
  return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace fissure
