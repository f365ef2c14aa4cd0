#include "tendril/envs/sma_limb/open_loop_inputs.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

ThrottleSequence open_loop_inputs(const std::string& kind, int64_t steps, double amplitude,
                                  int64_t period) {
  require(steps >= 0 && period >= 4 && period % 4 == 0,
          "needs steps >= 0 and a period that is a positive multiple of 4", "open_loop_inputs");
  ThrottleSequence inputs(steps, 2);
  const double p = static_cast<double>(period);
  auto ramp = [&](int64_t k) { return -1.0 + 2.0 * static_cast<double>(k % period) / p; };
  for (int64_t k = 0; k < steps; ++k) {
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(k) / p;
    if (kind == "sine") {
      inputs.row(k) << std::sin(phase), std::cos(phase);
    } else if (kind == "square") {
      const int64_t quarter = (k % period) / (period / 4);
      const double signs[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
      inputs.row(k) << signs[quarter][0], signs[quarter][1];
    } else if (kind == "sawtooth") {
      inputs.row(k) << ramp(k), ramp(k + period / 4);
    } else {
      throw Error("unknown open-loop input '" + kind + "' (expected sine, square or sawtooth)",
                  "open_loop_inputs");
    }
  }
  return inputs * amplitude;
}

}  // namespace tendril::envs::sma_limb
