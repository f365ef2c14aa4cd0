#include "tendril/envs/sma_limb/power_proxy.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

PowerProxy::PowerProxy(Params params) : params_(params) {
  require(std::isfinite(params.cooling_rate) && params.cooling_rate > 0.0 &&
              std::isfinite(params.period) && params.period > 0.0 &&
              std::isfinite(params.resistance) && params.resistance > 0.0 &&
              params.cooling_rate * params.period < 1.0,
          "power proxy needs k, dt, R > 0 and k·dt < 1, got k = " +
              std::to_string(params.cooling_rate) + ", dt = " + std::to_string(params.period) +
              ", R = " + std::to_string(params.resistance),
          "sma_limb::PowerProxy");
}

double PowerProxy::bound(double max_throttle) const {
  return max_throttle * max_throttle / (params_.resistance * params_.cooling_rate);
}

void PowerProxy::update(double throttle_x, double throttle_y) {
  power_ *= 1.0 - params_.cooling_rate * params_.period;
  const double heat_x = throttle_x * throttle_x / params_.resistance * params_.period;
  const double heat_y = throttle_y * throttle_y / params_.resistance * params_.period;
  power_[throttle_x > 0.0 ? 0 : 1] += heat_x;
  power_[throttle_y > 0.0 ? 2 : 3] += heat_y;
}

void PowerProxy::save_state(SnapshotWriter& out) const {
  out.section("PowerProxy");
  out.put_matrix(power_);
}

void PowerProxy::load_state(SnapshotReader& in) {
  in.section("PowerProxy");
  Eigen::Vector4d power;
  in.get_matrix(power);
  power_ = power;
}

}  // namespace tendril::envs::sma_limb
