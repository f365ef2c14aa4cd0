#include "tendril/rl/on_policy_algorithm.hpp"

#include <chrono>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

OnPolicyAlgorithm::OnPolicyAlgorithm(std::string name, envs::VecEnv& env,
                                     const OnPolicyConfig& common, uint64_t seed)
    : Algorithm(std::move(name), env, seed),
      common_(common),
      policy_(env.observation_space(), env.action_space(), common.policy),
      buffer_(common.n_steps, env.num_envs(), env.observation_space().size(),
              policy_.network().action_dims()) {
  common_.validate(this->name());
  common_.policy = policy_.network().spec();
  Rng init_rng = init_stream();
  policy_.network().initialize(policy_.parameters(), init_rng);
}

void OnPolicyAlgorithm::collect_rollout(Progress& progress, const Observers& observers) {
  const int n_envs = env().num_envs();
  const auto observation_size = env().observation_space().size();
  buffer_.clear();
  truncation_values_.setZero(n_envs);
  while (!buffer_.full()) {
    auto start = Clock::now();
    const envs::BatchMatrix& current = current_observations();
    // Columns of this view are the envs' observations (the row-major batch read in place).
    const Eigen::Map<const Eigen::MatrixXf> observations(current.data(), observation_size, n_envs);
    policy_.sample(observations, stream(Stream::kActions), actions_, log_probs_);
    policy_.values(observations, values_);
    clipped_actions_ = actions_;
    clip_to_bounds(env().action_space(), clipped_actions_);
    env_actions_ = clipped_actions_.transpose();
    progress.inference_seconds += seconds_since(start);

    start = Clock::now();
    // The buffer stores the observations the actions were chosen from: add them before the
    // step replaces the current ones.
    const envs::BatchMatrix observed = current;
    const envs::VecStep& step = step_environments(env_actions_, observers);
    progress.env_seconds += seconds_since(start);

    start = Clock::now();
    // Bootstrap through time-limit truncation from the episode's final observation.
    bool any_truncated = false;
    for (int i = 0; i < n_envs; ++i) any_truncated = any_truncated || step.truncated[i];
    if (any_truncated) {
      const Eigen::Map<const Eigen::MatrixXf> finals(step.final_observations.data(),
                                                     observation_size, n_envs);
      policy_.values(finals, truncation_values_);
    }
    buffer_.add(observed, actions_, step.rewards, values_, log_probs_, step.terminated,
                step.truncated, truncation_values_);
    progress.inference_seconds += seconds_since(start);
  }
  const auto start = Clock::now();
  const envs::BatchMatrix& current = current_observations();
  const Eigen::Map<const Eigen::MatrixXf> observations(current.data(), observation_size, n_envs);
  policy_.values(observations, last_values_);
  buffer_.finish(last_values_, common_.gamma, common_.gae_lambda);
  progress.inference_seconds += seconds_since(start);
}

void OnPolicyAlgorithm::run(int64_t total_timesteps, const Observers& observers) {
  while (num_timesteps() < total_timesteps) {
    Progress progress;
    collect_rollout(progress, observers);
    const auto start = Clock::now();
    progress.train = train(progress_remaining());
    progress.update_seconds = seconds_since(start);
    if (!finish_iteration(progress, observers)) break;
  }
}

void OnPolicyAlgorithm::write_state(ArchiveWriter& writer) const {
  writer.put_floats("policy_parameters", policy_.parameters());
  write_optimizers(writer);
}

std::function<void()> OnPolicyAlgorithm::read_state(const ArchiveReader& reader) {
  Eigen::VectorXf parameters = reader.get_floats("policy_parameters", policy_.parameters().size());
  require(parameters.allFinite(), "the checkpoint's policy parameters are not finite",
          reader.name());
  std::function<void()> install_optimizers = read_optimizers(reader);
  return [this, parameters = std::move(parameters), install_optimizers] {
    policy_.parameters() = parameters;
    install_optimizers();
  };
}

}  // namespace tendril::rl
