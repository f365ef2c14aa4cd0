#include "tendril/rl/off_policy_algorithm.hpp"

#include <algorithm>
#include <chrono>

#include "tendril/core/error.hpp"
#include "tendril/nn/blas.hpp"
#include "tendril/rl/normalizer_state.hpp"

namespace tendril::rl {

namespace {

constexpr int64_t kCheckpointFormat = 1;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Rng streams derived from the seed, one per purpose (the algorithms derive their own
// initialisation streams from the seed with ids from 100 on).
enum Stream : uint64_t { kActions = 1, kSamples, kPredict, kEnvSeeds };

}  // namespace

OffPolicyAlgorithm::OffPolicyAlgorithm(std::string name, envs::VecEnv& env,
                                       const OffPolicyConfig& common, uint64_t seed)
    : name_(std::move(name)),
      env_(env),
      common_(common),
      seed_(seed),
      buffer_(common.buffer_size, env.observation_space().size(), env.action_space().size()),
      action_rng_(seed, kActions),
      sample_rng_(seed, kSamples),
      predict_rng_(seed, kPredict),
      env_seed_rng_(seed, kEnvSeeds) {
  common_.validate(name_ + " config");
  const Space& actions = env.action_space();
  require(actions.is_discrete() || actions.bounded(),
          name_ +
              " needs finite action bounds to scale actions to [-1, 1], but the action space "
              "is " +
              actions.describe(),
          name_);
}

double OffPolicyAlgorithm::progress_remaining() const {
  const double done = static_cast<double>(num_timesteps_) / static_cast<double>(total_timesteps_);
  return std::clamp(1.0 - done, 0.0, 1.0);
}

void OffPolicyAlgorithm::to_env_actions(const Eigen::MatrixXf& actions,
                                        envs::BatchMatrix& env_actions) const {
  env_actions.resize(actions.cols(), actions.rows());
  const Space& space = env_.action_space();
  if (space.is_discrete()) {
    env_actions = actions.transpose();
    return;
  }
  // [−1, 1] → [low, high] (SB3's unscale_action), clipped first as SB3 clips its noisy actions.
  const Eigen::ArrayXf half_range = 0.5f * (space.high() - space.low()).array();
  for (Eigen::Index i = 0; i < actions.cols(); ++i) {
    const Eigen::ArrayXf scaled = actions.col(i).array().cwiseMax(-1.0f).cwiseMin(1.0f);
    env_actions.row(i) = (space.low().array() + (scaled + 1.0f) * half_range).matrix().transpose();
  }
}

void OffPolicyAlgorithm::collect(Progress& progress) {
  const int n_envs = env_.num_envs();
  const Space& space = env_.action_space();
  collection_started();
  for (int64_t k = 0; k < common_.train_freq; ++k) {
    auto start = Clock::now();
    if (needs_reset_) {
      last_observations_ = env_.reset(env_seed_rng_.next_u64());
      needs_reset_ = false;
    }
    const Eigen::Map<const Eigen::MatrixXf> observations(last_observations_.data(),
                                                         observation_size(), n_envs);
    if (num_timesteps_ < common_.learning_starts) {
      // Warm-up: uniformly random actions (SB3's action_space.sample(), here already scaled).
      actions_.resize(action_size(), n_envs);
      for (int i = 0; i < n_envs; ++i) {
        for (int j = 0; j < action_size(); ++j) {
          actions_(j, i) =
              space.is_discrete()
                  ? static_cast<float>(action_rng_.below(static_cast<uint64_t>(space.n())))
                  : static_cast<float>(action_rng_.uniform(-1.0, 1.0));
        }
      }
    } else {
      act(observations, ActMode::kCollect, action_rng_, actions_);
    }
    to_env_actions(actions_, env_actions_);
    progress.inference_seconds += seconds_since(start);

    start = Clock::now();
    const envs::VecStep& step = env_.step(env_actions_);
    progress.env_seconds += seconds_since(start);

    start = Clock::now();
    for (int i = 0; i < n_envs; ++i) {
      buffer_.add(observations.col(i), actions_.col(i), step.rewards[i],
                  step.final_observations.row(i).transpose(), step.terminated[i] != 0);
      if (step.done(i)) episode_ended(i);
    }
    episodes_.record(step);
    last_observations_ = step.observations;
    num_timesteps_ += n_envs;
    after_step();
    progress.inference_seconds += seconds_since(start);
  }
}

void OffPolicyAlgorithm::learn(int64_t total_timesteps, const Callback& callback) {
  total_timesteps_ = std::max<int64_t>(total_timesteps, 1);
  nn::set_blas_threads(common_.learner_threads);
  while (num_timesteps_ < total_timesteps) {
    Progress progress;
    const int64_t block_start = num_timesteps_;
    while (num_timesteps_ - block_start < common_.log_interval &&
           num_timesteps_ < total_timesteps) {
      collect(progress);
      if (num_timesteps_ <= common_.learning_starts) continue;
      const int64_t gradient_steps = common_.gradient_steps >= 0
                                         ? common_.gradient_steps
                                         : common_.train_freq * env_.num_envs();
      if (gradient_steps == 0) continue;
      const auto start = Clock::now();
      progress.train = train(gradient_steps, progress_remaining());
      progress.update_seconds += seconds_since(start);
    }
    ++iterations_;
    progress.train.emplace_back("train/n_updates", static_cast<double>(updates_));
    progress.timesteps = num_timesteps_;
    progress.iterations = iterations_;
    episodes_.report(progress);
    if (callback && !callback(progress)) break;
  }
}

envs::BatchMatrix OffPolicyAlgorithm::predict(const envs::BatchMatrix& observations,
                                              bool deterministic) {
  check_observations(observations, static_cast<int>(observation_size()), name_ + "::predict");
  const Eigen::Map<const Eigen::MatrixXf> columns(observations.data(), observation_size(),
                                                  observations.rows());
  Eigen::MatrixXf actions;
  act(columns, deterministic ? ActMode::kDeterministic : ActMode::kStochastic, predict_rng_,
      actions);
  envs::BatchMatrix result;
  to_env_actions(actions, result);
  return result;
}

void OffPolicyAlgorithm::save(const std::filesystem::path& file) const {
  CheckpointWriter writer;
  writer.write_int("format", kCheckpointFormat);
  writer.write_string("algorithm", name_);
  writer.write_int("observation_size", observation_size());
  writer.write_int("action_size", action_size());
  writer.write_rng("rng_actions", action_rng_.state());
  writer.write_rng("rng_samples", sample_rng_.state());
  writer.write_rng("rng_predict", predict_rng_.state());
  writer.write_rng("rng_env_seeds", env_seed_rng_.state());
  writer.write_int("num_timesteps", num_timesteps_);
  writer.write_int("iterations", iterations_);
  writer.write_int("updates", updates_);
  episodes_.save(writer);
  save_normalizers(env_, writer);
  save_state(writer);
  writer.commit(file);
}

void OffPolicyAlgorithm::load(const std::filesystem::path& file) {
  CheckpointReader reader(file);
  const std::string where = file.string();
  require(reader.read_int("format") == kCheckpointFormat, "unsupported checkpoint format", where);
  const std::string algorithm = reader.read_string("algorithm");
  require(algorithm == name_, "checkpoint of " + algorithm + ", not " + name_, where);
  const auto expect = [&](const char* key, int64_t expected) {
    const int64_t found = reader.read_int(key);
    require(found == expected,
            std::string(key) + " is " + std::to_string(found) + " in the checkpoint, " +
                std::to_string(expected) + " here",
            where);
  };
  expect("observation_size", observation_size());
  expect("action_size", action_size());
  const Rng::State actions = reader.read_rng("rng_actions");
  const Rng::State samples = reader.read_rng("rng_samples");
  const Rng::State predict = reader.read_rng("rng_predict");
  const Rng::State env_seeds = reader.read_rng("rng_env_seeds");
  const int64_t timesteps = reader.read_int("num_timesteps");
  const int64_t iterations = reader.read_int("iterations");
  const int64_t updates = reader.read_int("updates");
  const std::function<void()> install_episodes = episodes_.prepare_load(reader);
  const std::function<void()> install_normalizers = prepare_normalizers(env_, reader);
  const std::function<void()> install_state = prepare_load(reader);

  action_rng_.set_state(actions);
  sample_rng_.set_state(samples);
  predict_rng_.set_state(predict);
  env_seed_rng_.set_state(env_seeds);
  num_timesteps_ = timesteps;
  iterations_ = iterations;
  updates_ = updates;
  install_episodes();
  install_normalizers();
  install_state();
  needs_reset_ = true;
}

}  // namespace tendril::rl
