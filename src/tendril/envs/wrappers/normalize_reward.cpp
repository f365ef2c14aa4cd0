#include "tendril/envs/wrappers/normalize_reward.hpp"

#include <string>

namespace tendril::envs {

NormalizeReward::NormalizeReward(std::unique_ptr<Env> inner, Options options)
    : Wrapper(std::move(inner)), options_(options) {
  const std::string where = "envs::NormalizeReward";
  require(options.gamma >= 0.0 && options.gamma <= 1.0, "gamma must lie in [0, 1]", where);
  require(options.clip > 0.0, "clip must be positive", where);
  require(options.epsilon > 0.0, "epsilon must be positive", where);
}

double NormalizeReward::normalize(double raw) const {
  return statistics_.scale(raw, options_.epsilon, options_.clip);
}

Observation NormalizeReward::reset(std::optional<uint64_t> seed) {
  discounted_return_ = 0.0;
  return inner_->reset(seed);
}

Step NormalizeReward::step(const Action& action) {
  Step result = inner_->step(action);
  if (training_) {
    discounted_return_ = discounted_return_ * options_.gamma + result.reward;
    statistics_.update(Eigen::VectorXd::Constant(1, discounted_return_));
  }
  result.reward = normalize(result.reward);
  if (result.terminated || result.truncated) discounted_return_ = 0.0;
  return result;
}

void NormalizeReward::set_statistics(const RunningMeanStd& statistics) {
  require(statistics.size() == 1, "reward statistics must have one component",
          "envs::NormalizeReward");
  statistics_ = statistics;
}

void NormalizeReward::import_statistics(std::span<const double> values) {
  statistics_ = RunningMeanStd::from_array(values, 1);
}

}  // namespace tendril::envs
