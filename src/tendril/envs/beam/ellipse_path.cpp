#include "tendril/envs/beam/ellipse_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::beam {

std::vector<EllipseLevel> EllipseSpec::default_levels(const EllipseLevel& full) {
  const auto around = [](double value, const Range& range) {
    const double quarter = 0.25 * (range.high - range.low);
    return Range{std::max(range.low, value - quarter), std::min(range.high, value + quarter)};
  };
  const double a = std::clamp(0.2, full.semi_major_axis.low, full.semi_major_axis.high);
  const double e = std::clamp(0.6, full.eccentricity.low, full.eccentricity.high);
  const double omega = std::clamp(0.5, full.angular_velocity.low, full.angular_velocity.high);
  const EllipseLevel fixed{{a, a}, {e, e}, {omega, omega}};
  const EllipseLevel middle{around(a, full.semi_major_axis), around(e, full.eccentricity),
                            around(omega, full.angular_velocity)};
  return {fixed, middle, full};
}

void EllipseSpec::validate() const {
  require(!levels.empty(), "an ellipse needs at least one level", "EllipseSpec levels");
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const std::string level = "EllipseSpec levels[" + std::to_string(i) + "].";
    levels[i].semi_major_axis.validate(level + "semi_major_axis", 1e-3, 10.0);
    levels[i].eccentricity.validate(level + "eccentricity", 0.0, 0.999);
    levels[i].angular_velocity.validate(level + "angular_velocity", 0.0, 100.0);
  }
  require(std::isfinite(top), "top must be finite", "EllipseSpec");
}

EllipsePath::EllipsePath(EllipseSpec spec) : spec_(std::move(spec)) {
  spec_.validate();
  level_ = levels() - 1;
}

void EllipsePath::reset(Rng& rng) {
  const EllipseLevel& level = spec_.levels[level_];
  semi_major_axis_ = level.semi_major_axis.sample(rng);
  eccentricity_ = level.eccentricity.sample(rng);
  angular_velocity_ = level.angular_velocity.sample(rng);
  phase_ = 0.0;
}

void EllipsePath::advance(Rng& /*rng*/, double dt) { phase_ += angular_velocity_ * dt; }

double EllipsePath::semi_minor_axis() const {
  return semi_major_axis_ * std::sqrt(1.0 - eccentricity_ * eccentricity_);
}

Eigen::Vector2d EllipsePath::position() const {
  return {semi_major_axis_ * std::sin(phase_),
          spec_.top - semi_minor_axis() * (1.0 - std::cos(phase_))};
}

Eigen::Vector2d EllipsePath::velocity() const {
  return angular_velocity_ * Eigen::Vector2d(semi_major_axis_ * std::cos(phase_),
                                             -semi_minor_axis() * std::sin(phase_));
}

Eigen::Matrix2Xd EllipsePath::polyline(int points) const {
  Eigen::Matrix2Xd line(2, points);
  const double b = semi_minor_axis();
  for (int k = 0; k < points; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / std::max(1, points - 1);
    line.col(k) << semi_major_axis_ * std::sin(theta), spec_.top - b * (1.0 - std::cos(theta));
  }
  return line;
}

void EllipsePath::save_state(SnapshotWriter& out) const {
  out.section("EllipsePath");
  out.put(static_cast<int64_t>(level_));
  out.put(semi_major_axis_);
  out.put(eccentricity_);
  out.put(angular_velocity_);
  out.put(phase_);
}

void EllipsePath::load_state(SnapshotReader& in) {
  in.section("EllipsePath");
  const int64_t level = in.get_int64();
  require(level >= 0 && level < levels(), "snapshot level outside this ellipse's levels",
          "EllipsePath::load_state");
  const double a = in.get_double();
  const double e = in.get_double();
  const double omega = in.get_double();
  const double phase = in.get_double();
  level_ = static_cast<int>(level);
  semi_major_axis_ = a;
  eccentricity_ = e;
  angular_velocity_ = omega;
  phase_ = phase;
}

}  // namespace tendril::envs::beam
