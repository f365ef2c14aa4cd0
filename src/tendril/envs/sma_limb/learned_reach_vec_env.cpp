#include "tendril/envs/sma_limb/learned_reach_vec_env.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/sma_limb/learned_reach_env.hpp"

namespace tendril::envs::sma_limb {

namespace {

constexpr const char* kWhere = "SmaLimb/LearnedReach-v0 (batched)";

void observe_into(const LearnedReachBatch& batch, int env, BatchMatrix& rows) {
  Eigen::VectorXf observation(rows.cols());
  batch.observe(env, observation);
  rows.row(env) = observation.transpose();
}

}  // namespace

LearnedReachVecEnv::LearnedReachVecEnv(std::shared_ptr<DynamicsModel> model,
                                       LearnedReachOptions options, int num_envs, uint64_t seed,
                                       std::optional<int64_t> max_episode_steps)
    : batch_(std::move(model), options, num_envs, seed),
      max_episode_steps_(max_episode_steps),
      observation_space_(batch_.observation_space()),
      action_space_(LearnedReachBatch::action_space()),
      episodes_(num_envs),
      next_reset_seeds_(static_cast<std::size_t>(num_envs)) {
  const int n = batch_.num_envs();
  const int size = observation_space_.size();
  result_.observations = BatchMatrix::Zero(n, size);
  result_.final_observations = BatchMatrix::Zero(n, size);
  result_.rewards = Eigen::VectorXf::Zero(n);
  result_.terminated.assign(n, 0);
  result_.truncated.assign(n, 0);
  result_.infos.assign(n, Info{});
}

std::unique_ptr<VecEnv> LearnedReachVecEnv::create(const Config& params, int num_envs,
                                                   std::optional<int64_t> max_episode_steps) {
  const uint64_t seed = params.get_or<uint64_t>("seed", 0);
  LearnedReachOptions options = LearnedReachOptions::from_config(params);
  return std::make_unique<LearnedReachVecEnv>(LearnedReachEnv::open_model(params), options,
                                              num_envs, seed, max_episode_steps);
}

void LearnedReachVecEnv::seed_next_reset(int env, uint64_t seed) {
  require(env >= 0 && env < num_envs(), "no environment " + std::to_string(env), kWhere);
  next_reset_seeds_.at(static_cast<std::size_t>(env)) = seed;
}

const BatchMatrix& LearnedReachVecEnv::reset(std::optional<uint64_t> seed) {
  next_reset_seeds_.assign(static_cast<std::size_t>(num_envs()), std::nullopt);
  for (int i = 0; i < num_envs(); ++i) {
    batch_.reset(i,
                 seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i)) : std::nullopt);
    episodes_[i] = Episode{};
    observe_into(batch_, i, result_.observations);
  }
  ready_ = true;
  return result_.observations;
}

const VecStep& LearnedReachVecEnv::step(const BatchMatrix& actions) {
  require(ready_, "step called before reset (or after an error)", kWhere);
  if (actions.rows() != num_envs() || actions.cols() != action_space_.size()) {
    throw Error("actions are " + std::to_string(actions.rows()) + " x " +
                    std::to_string(actions.cols()) + ", expected " + std::to_string(num_envs()) +
                    " x " + std::to_string(action_space_.size()) + " (envs x action size)",
                kWhere);
  }
  try {
    batch_.step(actions);
  } catch (...) {
    ready_ = false;
    throw;
  }
  for (int i = 0; i < num_envs(); ++i) {
    Episode& episode = episodes_[i];
    const bool terminated = batch_.terminated(i);
    episode.episode_return += batch_.reward(i);
    ++episode.length;
    const bool truncated =
        !terminated && max_episode_steps_ && episode.length >= *max_episode_steps_;
    result_.rewards[i] = static_cast<float>(batch_.reward(i));
    result_.terminated[i] = terminated ? 1 : 0;
    result_.truncated[i] = truncated ? 1 : 0;
    result_.infos[i] = batch_.info(i);
    observe_into(batch_, i, result_.final_observations);
    if (terminated || truncated) {
      result_.infos[i].set(info_keys::kEpisodeReturn, episode.episode_return);
      result_.infos[i].set(info_keys::kEpisodeLength, static_cast<double>(episode.length));
      episode = Episode{};
      batch_.reset(i, next_reset_seeds_[static_cast<std::size_t>(i)]);
      next_reset_seeds_[static_cast<std::size_t>(i)].reset();
      observe_into(batch_, i, result_.observations);
    } else {
      result_.observations.row(i) = result_.final_observations.row(i);
    }
  }
  return result_;
}

void LearnedReachVecEnv::save_state(SnapshotWriter& out, bool environments) const {
  out.section(kWhere);
  out.put(static_cast<int64_t>(num_envs()));
  const bool with_envs = environments && ready_;
  out.put(with_envs);
  if (!with_envs) return;
  batch_.save_state(out);
  for (const Episode& episode : episodes_) {
    out.put(episode.episode_return);
    out.put(episode.length);
  }
}

bool LearnedReachVecEnv::load_state(SnapshotReader& in) {
  in.section(kWhere);
  const int64_t count = in.get_int64();
  require(count == num_envs(),
          "snapshot of " + std::to_string(count) + " environments, this vector env has " +
              std::to_string(num_envs()),
          kWhere);
  if (!in.get_bool()) return false;
  ready_ = false;
  batch_.load_state(in);
  for (Episode& episode : episodes_) {
    episode.episode_return = in.get_double();
    episode.length = in.get_int64();
  }
  for (int i = 0; i < num_envs(); ++i) {
    observe_into(batch_, i, result_.observations);
  }
  ready_ = true;
  return true;
}

}  // namespace tendril::envs::sma_limb
