#include "tendril/envs/sma_limb/throttle_sources.hpp"

#include <algorithm>

namespace tendril::envs::sma_limb {

CountBasedExploration::CountBasedExploration(Rule rule, VisitGrid grid)
    : rule_(rule), grid_(std::move(grid)) {}

int CountBasedExploration::sample_cell(Rng& rng) const {
  const int64_t m = grid_.max_count();
  double total = 0.0;
  for (int64_t count : grid_.counts()) total += static_cast<double>(m + 1 - count);
  double r = rng.uniform(0.0, total);
  for (int c = 0; c < grid_.cells(); ++c) {
    r -= static_cast<double>(m + 1 - grid_.counts()[c]);
    if (r <= 0.0) return c;
  }
  return grid_.cells() - 1;  // r = total up to rounding
}

Eigen::Vector2i CountBasedExploration::uniform_action(const Eigen::Vector2d& angles_deg, int target,
                                                      Rng& rng) const {
  const Eigen::Vector2d centre = grid_.centre(target);
  Eigen::Vector2i throttles;
  for (int axis = 0; axis < 2; ++axis) {
    const int magnitude = 1 + static_cast<int>(rng.below(10));
    throttles[axis] = angles_deg[axis] < centre[axis] ? magnitude : -magnitude;
  }
  return throttles;
}

Eigen::Vector2i CountBasedExploration::walk_action(const Eigen::Vector2d& angles_deg, int target,
                                                   Rng& rng) {
  const int n = grid_.cells_per_axis();
  const int current = grid_.cell(angles_deg);
  Eigen::Vector2i direction(target % n - current % n, target / n - current / n);
  if ((angles_deg - grid_.centre(target)).norm() <= kArrivedDeg) {
    static constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    static constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    const int neighbour = static_cast<int>(rng.below(8));
    direction = Eigen::Vector2i(kDx[neighbour], kDy[neighbour]);
  }
  for (int axis = 0; axis < 2; ++axis) {
    const int step = static_cast<int>(rng.below(kMaxStep + 1));
    int& u = throttles_[axis];
    if (direction[axis] > 0) {
      u += step;
    } else if (direction[axis] < 0) {
      u -= step;
    } else if (u != 0) {
      u += u > 0 ? -step : step;  // back towards zero, possibly past it
    }
    u = std::clamp(u, -10, 10);
  }
  return throttles_;
}

Eigen::Vector2i CountBasedExploration::next(const Eigen::Vector2d& angles_deg, Rng& rng) {
  const int target = sample_cell(rng);
  return rule_ == Rule::kUniform ? uniform_action(angles_deg, target, rng)
                                 : walk_action(angles_deg, target, rng);
}

Eigen::Vector2i MotorBabbling::next(const Eigen::Vector2d& /*angles_deg*/, Rng& rng) {
  const bool two = rng.below(2) == 1;
  const int coil = static_cast<int>(rng.below(4));  // +x, −x, +y, −y
  const int axis = coil / 2;
  Eigen::Vector2i throttles = Eigen::Vector2i::Zero();
  throttles[axis] = (coil % 2 == 0 ? 1 : -1) * static_cast<int>(rng.below(11));
  if (two) {
    const int sign = rng.below(2) == 0 ? 1 : -1;
    throttles[1 - axis] = sign * static_cast<int>(rng.below(11));
  }
  return throttles;
}

}  // namespace tendril::envs::sma_limb
