#include "tendril/envs/vector/vec_normalize.hpp"

#include <span>
#include <string>
#include <vector>

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

VecNormalize::VecNormalize(std::unique_ptr<VecEnv> inner, Options options)
    : VecEnvWrapper(std::move(inner)),
      options_(options),
      observation_space_(normalized_space(inner_->observation_space(), options)),
      observation_statistics_(inner_->observation_space().size()),
      returns_(Eigen::VectorXd::Zero(checked_num_envs(inner_->num_envs()))),
      batch_(inner_->num_envs(), inner_->observation_space().size()) {
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

const BatchMatrix& VecNormalize::reset(std::optional<uint64_t> seed) {
  observations_ = inner_->reset(seed);
  normalize_reset(observations_);
  return observations_;
}

const VecStep& VecNormalize::step(const BatchMatrix& actions) {
  result_ = inner_->step(actions);
  normalize_step(result_);
  return result_;
}

void VecNormalize::save_state(SnapshotWriter& out, bool environments) const {
  out.section("VecNormalize");
  out.put(std::span<const double>(observation_statistics_.to_array()));
  out.put(std::span<const double>(return_statistics_.to_array()));
  out.put_matrix(returns_);
  inner_->save_state(out, environments);
}

bool VecNormalize::load_state(SnapshotReader& in) {
  in.section("VecNormalize");
  std::vector<double> observation(1 + 2 * observation_statistics_.size());
  in.get(std::span<double>(observation));
  std::vector<double> returns_array(3);
  in.get(std::span<double>(returns_array));
  Eigen::VectorXd returns = returns_;
  in.get_matrix(returns);
  const RunningMeanStd observation_statistics =
      RunningMeanStd::from_array(observation, observation_statistics_.size());
  const RunningMeanStd return_statistics = RunningMeanStd::from_array(returns_array, 1);
  require(returns.allFinite(), "running returns must be finite", kWhere);
  const bool restored = inner_->load_state(in);
  observation_statistics_ = observation_statistics;
  return_statistics_ = return_statistics;
  returns_ = returns;
  return restored;
}

void VecNormalize::normalize_reset(BatchMatrix& observations) {
  returns_.setZero();
  if (!options_.normalize_observation) return;
  if (training_) {
    batch_ = observations.cast<double>();
    observation_statistics_.update_batch(batch_);
  }
  normalize_rows(observations);
}

void VecNormalize::normalize_step(VecStep& step) {
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
