#include "tendril/rl/action_noise.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::rl {

void ActionNoiseConfig::read(const Config& algo) {
  if (algo.has("noise_type")) {
    const std::string type = algo.get<std::string>("noise_type");
    if (type == "none") {
      kind = Kind::kNone;
    } else if (type == "normal") {
      kind = Kind::kNormal;
    } else if (type == "ornstein_uhlenbeck") {
      kind = Kind::kOrnsteinUhlenbeck;
    } else {
      throw Error(
          "unknown noise type '" + type + "', expected none, normal or ornstein_uhlenbeck",
          algo.source() + ": " + (algo.path().empty() ? "" : algo.path() + ".") + "noise_type");
    }
  }
  sigma = algo.get_or<double>("noise_std", sigma);
  theta = algo.get_or<double>("noise_theta", theta);
  dt = algo.get_or<double>("noise_dt", dt);
}

void ActionNoiseConfig::validate(const std::string& where) const {
  require(sigma >= 0.0, "noise_std must be non-negative", where);
  require(theta >= 0.0 && dt > 0.0, "noise_theta must be non-negative and noise_dt positive",
          where);
}

ActionNoise::ActionNoise(const ActionNoiseConfig& config, int num_envs, int action_size)
    : config_(config), state_(Eigen::MatrixXf::Zero(action_size, num_envs)) {}

void ActionNoise::add(Eigen::MatrixXf& actions, Rng& rng) {
  if (!active()) return;
  const double sigma = config_.sigma;
  for (Eigen::Index i = 0; i < actions.cols(); ++i) {
    for (Eigen::Index j = 0; j < actions.rows(); ++j) {
      float& noise = state_(j, i);
      if (config_.kind == ActionNoiseConfig::Kind::kNormal) {
        noise = static_cast<float>(sigma * rng.normal());
      } else {
        noise += static_cast<float>(-config_.theta * noise * config_.dt +
                                    sigma * std::sqrt(config_.dt) * rng.normal());
      }
      actions(j, i) += noise;
    }
  }
}

}  // namespace tendril::rl
