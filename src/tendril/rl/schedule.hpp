#pragma once

#include <string>

#include "tendril/core/config.hpp"

namespace tendril::rl {

// A hyper-parameter that may anneal over training (SB3's schedules): constant, or linear from
// `initial` at the start to 0 at the end of the budget. `progress_remaining` runs from 1 (first
// update) to 0 (budget spent), as in SB3.
struct Schedule {
  double initial = 0.0;
  bool linear = false;

  double at(double progress_remaining) const {
    return linear ? initial * progress_remaining : initial;
  }
};

// Reads `<key>` (a number) and `<key>_schedule` (constant | linear) from `algo` over `fallback`.
Schedule read_schedule(const Config& algo, const std::string& key, const Schedule& fallback);

}  // namespace tendril::rl
