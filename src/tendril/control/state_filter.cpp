#include "tendril/control/state_filter.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::control {

StateFilter::StateFilter(double alpha) : alpha_(alpha) {
  require(std::isfinite(alpha) && alpha > 0.0 && alpha <= 1.0, "ema_alpha must lie in (0, 1]",
          "StateFilter");
}

Eigen::Vector4d StateFilter::next(double time_s, const Eigen::Vector2d& angles_deg) const {
  Eigen::Vector4d raw;
  if (!started_) {
    raw << angles_deg, 0.0, 0.0;
    return raw;
  }
  const double dt = time_s - previous_time_;
  if (!(dt > 0.0)) throw Error("time stamps must increase", "StateFilter");
  raw << angles_deg, (angles_deg - previous_angles_) / dt;
  return alpha_ * raw + (1.0 - alpha_) * filtered_;
}

Eigen::Vector4d StateFilter::update(double time_s, const Eigen::Vector2d& angles_deg) {
  filtered_ = next(time_s, angles_deg);
  started_ = true;
  previous_time_ = time_s;
  previous_angles_ = angles_deg;
  return filtered_;
}

}  // namespace tendril::control
