#include "tendril/envs/elastica/target_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::elastica {

TargetMotion::TargetMotion(Params params) : params_(std::move(params)) {
  const char* who = "elastica::TargetMotion";
  require((params_.box_low.array() < params_.box_high.array()).all(),
          "the box must have low < high in every coordinate", who);
  require(std::isfinite(params_.speed) && params_.speed >= 0.0, "speed must be finite, >= 0", who);
  require(std::isfinite(params_.time_step) && params_.time_step > 0.0,
          "time_step must be finite and positive", who);
  require(params_.steps_per_direction >= 1, "steps_per_direction must be at least 1", who);
  position_ = 0.5 * (params_.box_low + params_.box_high);
}

Eigen::Vector3d TargetMotion::random_direction(Rng& rng) const {
  // Uniform on the sphere (Archimedes): z uniform in [−1, 1], azimuth uniform in [0, 2π).
  const double z = rng.uniform(-1.0, 1.0);
  const double azimuth = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {ring * std::cos(azimuth), ring * std::sin(azimuth), z};
}

void TargetMotion::reset(Rng& rng) {
  for (int c = 0; c < 3; ++c) position_[c] = rng.uniform(params_.box_low[c], params_.box_high[c]);
  velocity_ = params_.speed * random_direction(rng);
  updates_ = 0;
}

void TargetMotion::advance(Rng& rng) {
  if (updates_ > 0 && updates_ % params_.steps_per_direction == 0) {
    velocity_ = params_.speed * random_direction(rng);
  }
  ++updates_;
  const Eigen::Vector3d previous = position_;
  position_ += params_.time_step * velocity_;
  for (int c = 0; c < 3; ++c) {
    const double low = params_.box_low[c], high = params_.box_high[c];
    if (position_[c] > high && previous[c] <= high) {
      position_[c] = std::max(low, 2.0 * high - position_[c]);
      velocity_[c] = -std::abs(velocity_[c]);
    } else if (position_[c] < low && previous[c] >= low) {
      position_[c] = std::min(high, 2.0 * low - position_[c]);
      velocity_[c] = std::abs(velocity_[c]);
    }
  }
}

void TargetMotion::set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  set_state(position, velocity, updates_);
}

void TargetMotion::set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                             long updates) {
  require(position.allFinite() && velocity.allFinite() && updates >= 0,
          "target state must be finite with a non-negative update count",
          "elastica::TargetMotion::set_state");
  position_ = position;
  velocity_ = velocity;
  updates_ = updates;
}

}  // namespace tendril::envs::elastica
