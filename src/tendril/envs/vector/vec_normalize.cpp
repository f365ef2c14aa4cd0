#include "tendril/envs/vector/vec_normalize.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

constexpr const char* kWhere = "envs::VecNormalize";

Space normalized_space(const Space& raw, const VecNormalize::Options& options) {
  if (!options.normalize_observation) return raw;
  require(raw.is_box(), "normalizing observations needs a Box space, got " + raw.describe(),
          kWhere);
  const auto clip = static_cast<float>(options.clip_observation);
  return Space::box(raw.size(), -clip, clip);
}

int checked_num_envs(int num_envs) {
  require(num_envs >= 1, "num_envs must be at least 1, got " + std::to_string(num_envs), kWhere);
  return num_envs;
}

}  // namespace

VecNormalize::VecNormalize(int num_envs, const Space& observation_space, Options options)
    : options_(options),
      observation_space_(normalized_space(observation_space, options)),
      observation_statistics_(observation_space.size()),
      returns_(Eigen::VectorXd::Zero(checked_num_envs(num_envs))),
      batch_(num_envs, observation_space.size()) {
  require(options.clip_observation > 0.0 && options.clip_reward > 0.0, "clips must be positive",
          kWhere);
  require(options.gamma >= 0.0 && options.gamma <= 1.0, "gamma must lie in [0, 1]", kWhere);
  require(options.epsilon > 0.0, "epsilon must be positive", kWhere);
}

void VecNormalize::normalize_rows(BatchMatrix& rows) const {
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    rows.row(i) = observation_statistics_
                      .normalize(rows.row(i).transpose().cast<double>(), options_.epsilon,
                                 options_.clip_observation)
                      .cast<float>()
                      .transpose();
  }
}

void VecNormalize::reset(BatchMatrix& observations) {
  returns_.setZero();
  if (!options_.normalize_observation) return;
  if (training_) {
    batch_ = observations.cast<double>();
    observation_statistics_.update_batch(batch_);
  }
  normalize_rows(observations);
}

void VecNormalize::step(VecStep& step) {
  if (options_.normalize_observation) {
    // The statistics see the observations handed out (first ones of new episodes where an
    // episode ended), not the final ones; both are normalized with the updated statistics.
    if (training_) {
      batch_ = step.observations.cast<double>();
      observation_statistics_.update_batch(batch_);
    }
    normalize_rows(step.observations);
    normalize_rows(step.final_observations);
  }
  if (options_.normalize_reward) {
    if (training_) {
      returns_ = returns_ * options_.gamma + step.rewards.cast<double>();
      return_statistics_.update_batch(returns_);
    }
    for (int i = 0; i < num_envs(); ++i) {
      step.rewards[i] = static_cast<float>(
          return_statistics_.scale(step.rewards[i], options_.epsilon, options_.clip_reward));
      if (step.done(i)) returns_[i] = 0.0;
    }
  }
}

void VecNormalize::set_observation_statistics(const RunningMeanStd& statistics) {
  require(statistics.size() == observation_statistics_.size(),
          "observation statistics have " + std::to_string(statistics.size()) +
              " components, observations " + std::to_string(observation_statistics_.size()),
          kWhere);
  observation_statistics_ = statistics;
}

void VecNormalize::set_return_state(const RunningMeanStd& statistics,
                                    const Eigen::VectorXd& returns) {
  require(statistics.size() == 1, "return statistics must have one component", kWhere);
  require(returns.size() == num_envs(),
          "got " + std::to_string(returns.size()) + " running returns for " +
              std::to_string(num_envs()) + " environments",
          kWhere);
  require(returns.allFinite(), "running returns must be finite", kWhere);
  return_statistics_ = statistics;
  returns_ = returns;
}

}  // namespace tendril::envs
