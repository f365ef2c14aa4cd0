#pragma once

namespace tendril::nn {

// ½ log 2π, the constant of every Gaussian log-density here:
//   log N(x; μ, σ²) = −½ ((x − μ)/σ)² − log σ − ½ log 2π.
inline constexpr double kHalfLogTwoPi = 0.91893853320467274178;
inline constexpr float kHalfLogTwoPiF = 0.91893853320467274178f;

}  // namespace tendril::nn
