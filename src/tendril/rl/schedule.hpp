#pragma once

#include <string>

#include "tendril/core/config.hpp"

namespace tendril::rl {

// A hyper-parameter that may anneal over training (SB3's schedules): constant, or linear from
// `initial` at the start to `final` (0 by default, as SB3) at the end of the budget — seed 002
// decays its learning rates linearly to a floor (actor 0.003 → 0.0001). `progress_remaining`
// runs from 1 (first update) to 0 (budget spent), as in SB3.
struct Schedule {
  double initial = 0.0;
  bool linear = false;
  double final = 0.0;

  double at(double progress_remaining) const {
    return linear ? final + (initial - final) * progress_remaining : initial;
  }
};

// Reads `<key>` (a number), `<key>_schedule` (constant | linear) and `<key>_final` (a linear
// schedule's end value) from `algo` over `fallback`.
Schedule read_schedule(const Config& algo, const std::string& key, const Schedule& fallback);

}  // namespace tendril::rl
