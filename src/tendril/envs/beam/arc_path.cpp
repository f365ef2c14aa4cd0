#include "tendril/envs/beam/arc_path.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::beam {

void ArcSpec::validate() const {
  require(!levels.empty(), "an arc needs at least one level", "ArcSpec levels");
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const std::string level = "ArcSpec levels[" + std::to_string(i) + "].";
    levels[i].radius.validate(level + "radius", 1e-3, 10.0);
    levels[i].angular_velocity.validate(level + "angular_velocity", 0.0, 100.0);
  }
  require(std::isfinite(arc_angle) && arc_angle > 0.0 && arc_angle < 360.0,
          "arc_angle must lie in (0, 360) degrees", "ArcSpec");
  require(std::isfinite(mean_reversal_interval) && mean_reversal_interval >= 0.0,
          "mean_reversal_interval must be non-negative", "ArcSpec");
}

ArcPath::ArcPath(ArcSpec spec)
    : spec_(std::move(spec)), half_angle_(0.5 * spec_.arc_angle * std::numbers::pi / 180.0) {
  spec_.validate();
  level_ = levels() - 1;
}

void ArcPath::reset(Rng& rng) {
  const ArcLevel& level = spec_.levels[level_];
  radius_ = level.radius.sample(rng);
  angular_velocity_ = level.angular_velocity.sample(rng);
  angle_ = rng.uniform(-half_angle_, half_angle_);
  direction_ = rng.uniform() < 0.5 ? -1.0 : 1.0;
}

void ArcPath::advance(Rng& rng, double dt) {
  // P(a flip within dt) for flips at rate 1/T; one draw per step either way, so the stream's
  // use does not depend on the outcome.
  const double flip = rng.uniform();
  if (spec_.mean_reversal_interval > 0.0 &&
      flip < -std::expm1(-dt / spec_.mean_reversal_interval)) {
    direction_ = -direction_;
  }
  angle_ += direction_ * angular_velocity_ * dt;
  if (angle_ > half_angle_) {
    angle_ = 2.0 * half_angle_ - angle_;
    direction_ = -1.0;
  } else if (angle_ < -half_angle_) {
    angle_ = -2.0 * half_angle_ - angle_;
    direction_ = 1.0;
  }
}

Eigen::Vector2d ArcPath::position() const {
  return radius_ * Eigen::Vector2d(std::sin(angle_), std::cos(angle_));
}

Eigen::Vector2d ArcPath::velocity() const {
  return direction_ * angular_velocity_ * radius_ *
         Eigen::Vector2d(std::cos(angle_), -std::sin(angle_));
}

Eigen::Matrix2Xd ArcPath::polyline(int points) const {
  Eigen::Matrix2Xd line(2, points);
  for (int k = 0; k < points; ++k) {
    const double phi = -half_angle_ + 2.0 * half_angle_ * k / std::max(1, points - 1);
    line.col(k) = radius_ * Eigen::Vector2d(std::sin(phi), std::cos(phi));
  }
  return line;
}

void ArcPath::set_state(double radius, double angular_velocity, double angle, double direction) {
  require(std::isfinite(radius) && radius > 0.0 && std::isfinite(angular_velocity) &&
              std::abs(angle) <= half_angle_ && (direction == 1.0 || direction == -1.0),
          "not a state on this arc", "ArcPath::set_state");
  radius_ = radius;
  angular_velocity_ = angular_velocity;
  angle_ = angle;
  direction_ = direction;
}

void ArcPath::save_state(SnapshotWriter& out) const {
  out.section("ArcPath");
  out.put(static_cast<int64_t>(level_));
  out.put(radius_);
  out.put(angular_velocity_);
  out.put(angle_);
  out.put(direction_);
}

void ArcPath::load_state(SnapshotReader& in) {
  in.section("ArcPath");
  const int64_t level = in.get_int64();
  require(level >= 0 && level < levels(), "snapshot level outside this arc's levels",
          "ArcPath::load_state");
  const double radius = in.get_double();
  const double angular_velocity = in.get_double();
  const double angle = in.get_double();
  const double direction = in.get_double();
  level_ = static_cast<int>(level);
  radius_ = radius;
  angular_velocity_ = angular_velocity;
  angle_ = angle;
  direction_ = direction;
}

}  // namespace tendril::envs::beam
