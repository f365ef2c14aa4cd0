#include "tendril/core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace tendril {

namespace {

std::atomic<int> caught{0};
static_assert(std::atomic<int>::is_always_lock_free,
              "the handler may only touch lock-free atomics");

extern "C" void record_signal(int signal) { caught.store(signal); }

}  // namespace

void catch_interrupts() {
  struct sigaction action = {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  // The second signal takes the default action; system calls the signal lands in restart
  // (worker threads may be reading or waiting when it arrives).
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return caught.load(); }

void request_interrupt(int signal) { caught.store(signal); }

void clear_interrupt() { caught.store(0); }

}  // namespace tendril
