#include "tendril/rl/off_policy_algorithm.hpp"

#include <chrono>

#include "tendril/core/error.hpp"
#include "tendril/nn/threads.hpp"

namespace tendril::rl {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

OffPolicyAlgorithm::OffPolicyAlgorithm(std::string name, envs::VecEnv& env,
                                       const OffPolicyConfig& common, uint64_t seed,
                                       int64_t stored_observation_size)
    : Algorithm(std::move(name), env, seed),
      common_(common),
      buffer_(
          common.buffer_size,
          stored_observation_size >= 0 ? stored_observation_size : env.observation_space().size(),
          env.action_space().size()) {
  common_.validate(this->name() + " config");
  const Space& actions = env.action_space();
  require(actions.is_discrete() || actions.bounded(),
          this->name() +
              " needs finite action bounds to scale actions to [-1, 1], but the action space "
              "is " +
              actions.describe(),
          this->name());
}

void OffPolicyAlgorithm::collect(Progress& progress, const Observers& observers) {
  const int n_envs = num_envs();
  const Space& space = action_space();
  collection_started();
  for (int64_t k = 0; k < common_.train_freq; ++k) {
    auto start = Clock::now();
    const envs::BatchMatrix& current = current_observations();
    const Eigen::Map<const Eigen::MatrixXf> observations(current.data(), observation_size(),
                                                         n_envs);
    if (num_timesteps() < common_.learning_starts) {
      // Warm-up: uniformly random actions (SB3's action_space.sample(), here already scaled).
      actions_.resize(action_size(), n_envs);
      Rng& rng = stream(Stream::kActions);
      for (int i = 0; i < n_envs; ++i) {
        for (int j = 0; j < action_size(); ++j) {
          actions_(j, i) = space.is_discrete()
                               ? static_cast<float>(rng.below(static_cast<uint64_t>(space.n())))
                               : static_cast<float>(rng.uniform(-1.0, 1.0));
        }
      }
    } else {
      explore(observations, stream(Stream::kActions), actions_);
    }
    env_action_columns_ = actions_;
    scale_to_bounds(space, env_action_columns_);
    env_actions_ = env_action_columns_.transpose();
    store_observations(observations, stored_);
    progress.inference_seconds += seconds_since(start);

    start = Clock::now();
    const envs::VecStep& step = step_environments(env_actions_, observers);
    progress.env_seconds += seconds_since(start);

    start = Clock::now();
    store_observations(step.final_observations.transpose(), stored_next_);
    for (int i = 0; i < n_envs; ++i) {
      buffer_.add(stored_.col(i), actions_.col(i), step.rewards[i], stored_next_.col(i),
                  step.terminated[i] != 0);
      if (step.done(i)) episode_ended(i);
    }
    after_step();
    progress.inference_seconds += seconds_since(start);
  }
}

void OffPolicyAlgorithm::run(int64_t total_timesteps, const Observers& observers) {
  const nn::BlasThreads blas_threads(common_.learner_threads);
  while (num_timesteps() < total_timesteps) {
    Progress progress;
    const int64_t block_start = num_timesteps();
    while (num_timesteps() - block_start < common_.log_interval &&
           num_timesteps() < total_timesteps) {
      collect(progress, observers);
      if (num_timesteps() <= common_.learning_starts) continue;
      const int64_t gradient_steps =
          common_.gradient_steps >= 0 ? common_.gradient_steps : common_.train_freq * num_envs();
      if (gradient_steps == 0) continue;
      const auto start = Clock::now();
      progress.train = train(gradient_steps, progress_remaining());
      progress.update_seconds += seconds_since(start);
    }
    progress.train.emplace_back("train/n_updates", static_cast<double>(updates_));
    if (!finish_iteration(progress, observers)) break;
  }
}

void OffPolicyAlgorithm::write_state(ArchiveWriter& writer) const {
  writer.put("updates", updates_);
  write_own_state(writer);
}

std::function<void()> OffPolicyAlgorithm::read_state(const ArchiveReader& reader) {
  const int64_t updates = reader.get_int("updates");
  require(updates >= 0, "negative update count", reader.name());
  std::function<void()> install = read_own_state(reader);
  return [this, updates, install] {
    updates_ = updates;
    install();
  };
}

TrainStats OffPolicyAlgorithm::train_on(const ReplayBuffer& buffer, int64_t gradient_steps,
                                        double progress_remaining) {
  require(buffer.observation_size() == buffer_.observation_size() &&
              buffer.action_size() == buffer_.action_size(),
          "the replay buffer's sizes differ from the algorithm's", name() + " train_on");
  require(buffer.size() > 0, "the replay buffer is empty", name() + " train_on");
  training_buffer_ = &buffer;
  try {
    TrainStats stats = train(gradient_steps, progress_remaining);
    training_buffer_ = nullptr;
    return stats;
  } catch (...) {
    training_buffer_ = nullptr;
    throw;
  }
}

}  // namespace tendril::rl
