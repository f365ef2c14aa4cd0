#pragma once

namespace tendril {

// A polite stop on SIGINT/SIGTERM: after `catch_interrupts()` the first such signal is only
// recorded, so long computations can finish their current step, save their state and return;
// a second signal of the same kind ends the process as the default action does.
void catch_interrupts();
// The signal recorded since the start or the last `clear_interrupt()`; 0 if none.
int interrupt_signal();
// Records `signal` as if it had been caught (tests, programmatic stops).
void request_interrupt(int signal);
void clear_interrupt();

}  // namespace tendril
