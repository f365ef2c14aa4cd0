#include "tendril/rl/on_policy_algorithm.hpp"

#include <chrono>

#include "tendril/core/error.hpp"
#include "tendril/nn/inference_sync.hpp"
#include "tendril/nn/threads.hpp"
#include "tendril/rl/normalizer_state.hpp"

namespace tendril::rl {

namespace {

constexpr int64_t kCheckpointFormat = 2;  // 2: PPO's Adam state as flat moment buffers

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Rng streams derived from the seed, one per purpose.
enum Stream : uint64_t { kInit = 1, kActions, kShuffle, kPredict, kEnvSeeds };

// Clips Box actions to the space's finite bounds, as SB3 does before stepping.
void clip_to_space(const Space& space, envs::BatchMatrix& actions) {
  if (!space.is_box()) return;
  for (Eigen::Index j = 0; j < actions.cols(); ++j) {
    const float low = space.low()[j];
    const float high = space.high()[j];
    actions.col(j) = actions.col(j).cwiseMax(low).cwiseMin(high);
  }
}

}  // namespace

OnPolicyAlgorithm::OnPolicyAlgorithm(std::string name, envs::VecEnv& env,
                                     const OnPolicyConfig& common, uint64_t seed)
    : name_(std::move(name)),
      env_(env),
      common_(common),
      seed_(seed),
      buffer_(common.n_steps, env.num_envs(), env.observation_space().size(),
              env.action_space().is_discrete() ? 1 : env.action_space().size()),
      action_rng_(seed, kActions),
      shuffle_rng_(seed, kShuffle),
      predict_rng_(seed, kPredict),
      env_seed_rng_(seed, kEnvSeeds) {
  common_.validate(name_);
  nn::use_one_torch_thread();
  torch::manual_seed(seed);
  common_.policy = common_.policy.with_spaces(env.observation_space(), env.action_space());
  Rng init_rng(seed, kInit);
  policy_ = nn::ActorCritic(common_.policy, init_rng);
  inference_ = nn::make_inference_policy(*policy_);
}

void OnPolicyAlgorithm::sync_inference() { nn::sync_inference_policy(*policy_, inference_); }

void OnPolicyAlgorithm::collect_rollout(Progress& progress) {
  const int n_envs = env_.num_envs();
  const auto observation_size = env_.observation_space().size();
  if (needs_reset_) {
    last_observations_ = env_.reset(env_seed_rng_.next_u64());
    needs_reset_ = false;
  }
  buffer_.clear();
  truncation_values_.setZero(n_envs);
  while (!buffer_.full()) {
    auto start = Clock::now();
    // Columns of this view are the envs' observations (the row-major batch read in place).
    const Eigen::Map<const Eigen::MatrixXf> observations(last_observations_.data(),
                                                         observation_size, n_envs);
    inference_.act(observations, /*deterministic=*/false, action_rng_, actions_, log_probs_);
    inference_.value(observations, values_);
    env_actions_ = actions_.transpose();
    clip_to_space(env_.action_space(), env_actions_);
    progress.inference_seconds += seconds_since(start);

    start = Clock::now();
    const envs::VecStep& step = env_.step(env_actions_);
    progress.env_seconds += seconds_since(start);

    start = Clock::now();
    // Bootstrap through time-limit truncation from the episode's final observation.
    bool any_truncated = false;
    for (int i = 0; i < n_envs; ++i) any_truncated = any_truncated || step.truncated[i];
    if (any_truncated) {
      const Eigen::Map<const Eigen::MatrixXf> finals(step.final_observations.data(),
                                                     observation_size, n_envs);
      inference_.value(finals, truncation_values_);
    }
    buffer_.add(last_observations_, actions_, step.rewards, values_, log_probs_, step.terminated,
                step.truncated, truncation_values_);
    episodes_.record(step);
    last_observations_ = step.observations;
    num_timesteps_ += n_envs;
    progress.inference_seconds += seconds_since(start);
  }
  const auto start = Clock::now();
  const Eigen::Map<const Eigen::MatrixXf> observations(last_observations_.data(), observation_size,
                                                       n_envs);
  inference_.value(observations, last_values_);
  buffer_.finish(last_values_, common_.gamma, common_.gae_lambda);
  progress.inference_seconds += seconds_since(start);
}

void OnPolicyAlgorithm::learn(int64_t total_timesteps, const Callback& callback) {
  nn::use_one_torch_thread();
  while (num_timesteps_ < total_timesteps) {
    Progress progress;
    collect_rollout(progress);
    ++iterations_;
    const double progress_remaining =
        1.0 - static_cast<double>(num_timesteps_) / static_cast<double>(total_timesteps);
    const auto start = Clock::now();
    progress.train = train(std::max(progress_remaining, 0.0));
    progress.update_seconds = seconds_since(start);

    progress.timesteps = num_timesteps_;
    progress.iterations = iterations_;
    episodes_.report(progress);
    if (callback && !callback(progress)) break;
  }
}

envs::BatchMatrix OnPolicyAlgorithm::predict(const envs::BatchMatrix& observations,
                                             bool deterministic) {
  const auto observation_size = env_.observation_space().size();
  check_observations(observations, static_cast<int>(observation_size), name_ + "::predict");
  const Eigen::Map<const Eigen::MatrixXf> columns(observations.data(), observation_size,
                                                  observations.rows());
  Eigen::MatrixXf actions;
  Eigen::VectorXf log_probs;
  inference_.act(columns, deterministic, predict_rng_, actions, log_probs);
  envs::BatchMatrix result = actions.transpose();
  clip_to_space(env_.action_space(), result);
  return result;
}

void OnPolicyAlgorithm::save(const std::filesystem::path& file) const {
  CheckpointWriter writer;
  writer.write_int("format", kCheckpointFormat);
  writer.write_string("algorithm", name_);
  writer.write_int("spec_observation_size", common_.policy.observation_size);
  writer.write_int("spec_action_size", common_.policy.action_size);
  writer.write_int("spec_discrete", common_.policy.discrete ? 1 : 0);
  torch::serialize::OutputArchive policy_archive;
  policy_->save(policy_archive);
  writer.archive().write("policy", policy_archive);
  save_optimizers(writer);
  writer.write_rng("rng_actions", action_rng_.state());
  writer.write_rng("rng_shuffle", shuffle_rng_.state());
  writer.write_rng("rng_predict", predict_rng_.state());
  writer.write_rng("rng_env_seeds", env_seed_rng_.state());
  writer.write_int("num_timesteps", num_timesteps_);
  writer.write_int("iterations", iterations_);
  episodes_.save(writer);
  save_normalizers(env_, writer);
  writer.commit(file);
}

void OnPolicyAlgorithm::load(const std::filesystem::path& file) {
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
  expect("spec_observation_size", common_.policy.observation_size);
  expect("spec_action_size", common_.policy.action_size);
  expect("spec_discrete", common_.policy.discrete ? 1 : 0);

  // Read everything into new objects first; install them only once all reads succeeded.
  Rng scratch_rng(0);
  nn::ActorCritic loaded(common_.policy, scratch_rng);
  reader.read_nested("policy",
                     [&](torch::serialize::InputArchive& archive) { loaded->load(archive); });
  const auto current = policy_->named_parameters();
  const auto restored = loaded->named_parameters();
  require(current.size() == restored.size(), "checkpoint has a different network", where);
  for (const auto& item : current) {
    const torch::Tensor* other = restored.find(item.key());
    require(other != nullptr && other->sizes() == item.value().sizes(),
            "parameter '" + item.key() + "' differs in shape from this network", where);
  }
  const std::function<void()> install_optimizers = prepare_load(reader, loaded);
  Rng::State actions = reader.read_rng("rng_actions");
  Rng::State shuffle = reader.read_rng("rng_shuffle");
  Rng::State predict = reader.read_rng("rng_predict");
  Rng::State env_seeds = reader.read_rng("rng_env_seeds");
  const int64_t timesteps = reader.read_int("num_timesteps");
  const int64_t iterations = reader.read_int("iterations");
  const std::function<void()> install_episodes = episodes_.prepare_load(reader);
  const std::function<void()> install_normalizers = prepare_normalizers(env_, reader);

  policy_ = loaded;
  install_optimizers();
  sync_inference();
  action_rng_.set_state(actions);
  shuffle_rng_.set_state(shuffle);
  predict_rng_.set_state(predict);
  env_seed_rng_.set_state(env_seeds);
  num_timesteps_ = timesteps;
  iterations_ = iterations;
  install_episodes();
  install_normalizers();
  needs_reset_ = true;
}

}  // namespace tendril::rl
