#include "tendril/envs/vector/batched_vec_env.hpp"

#include <utility>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs {

BatchedVecEnv::BatchedVecEnv(std::string name, std::optional<int64_t> max_episode_steps)
    : name_(std::move(name)), max_episode_steps_(max_episode_steps) {}

void BatchedVecEnv::allocate(int num_envs) {
  const auto n = static_cast<std::size_t>(num_envs);
  const int size = observation_space().size();
  episodes_.assign(n, Episode{});
  next_reset_seeds_.assign(n, std::nullopt);
  result_.observations = BatchMatrix::Zero(num_envs, size);
  result_.final_observations = BatchMatrix::Zero(num_envs, size);
  result_.rewards = Eigen::VectorXf::Zero(num_envs);
  result_.terminated.assign(n, 0);
  result_.truncated.assign(n, 0);
  result_.infos.assign(n, Info{});
}

void BatchedVecEnv::seed_next_reset(int env, uint64_t seed) {
  require(env >= 0 && env < num_envs(), "no environment " + std::to_string(env), name_);
  next_reset_seeds_[static_cast<std::size_t>(env)] = seed;
}

const BatchMatrix& BatchedVecEnv::reset(std::optional<uint64_t> seed) {
  ready_ = false;
  next_reset_seeds_.assign(static_cast<std::size_t>(num_envs()), std::nullopt);
  for (int i = 0; i < num_envs(); ++i) {
    reset_env(i, seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i)) : std::nullopt,
              result_.observations.row(i));
    episodes_[static_cast<std::size_t>(i)] = Episode{};
  }
  ready_ = true;
  return result_.observations;
}

const VecStep& BatchedVecEnv::step(const BatchMatrix& actions) {
  require(ready_, "step called before reset (or after an error)", name_);
  if (actions.rows() != num_envs() || actions.cols() != action_space().size()) {
    throw Error("actions are " + std::to_string(actions.rows()) + " x " +
                    std::to_string(actions.cols()) + ", expected " + std::to_string(num_envs()) +
                    " x " + std::to_string(action_space().size()) + " (envs x action size)",
                name_);
  }
  try {
    step_envs(actions);
    for (int i = 0; i < num_envs(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      Outcome step = outcome(i, result_.final_observations.row(i));
      Episode& episode = episodes_[k];
      episode.episode_return += step.reward;
      ++episode.length;
      const bool truncated =
          !step.terminated && max_episode_steps_ && episode.length >= *max_episode_steps_;
      result_.rewards[i] = static_cast<float>(step.reward);
      result_.terminated[k] = step.terminated ? 1 : 0;
      result_.truncated[k] = truncated ? 1 : 0;
      result_.infos[k] = std::move(step.info);
      if (step.terminated || truncated) {
        result_.infos[k].set(info_keys::kEpisodeReturn, episode.episode_return);
        result_.infos[k].set(info_keys::kEpisodeLength, static_cast<double>(episode.length));
        episode = Episode{};
        reset_env(i, next_reset_seeds_[k], result_.observations.row(i));
        next_reset_seeds_[k].reset();
      } else {
        result_.observations.row(i) = result_.final_observations.row(i);
      }
    }
  } catch (...) {
    ready_ = false;
    throw;
  }
  return result_;
}

void BatchedVecEnv::save_state(SnapshotWriter& out, bool environments) const {
  out.section(name_);
  out.put(static_cast<int64_t>(num_envs()));
  const bool with_envs = environments && ready_;
  out.put(with_envs);
  if (!with_envs) return;
  save_envs(out);
  for (const Episode& episode : episodes_) {
    out.put(episode.episode_return);
    out.put(episode.length);
  }
}

bool BatchedVecEnv::load_state(SnapshotReader& in) {
  in.section(name_);
  const int64_t count = in.get_int64();
  require(count == num_envs(),
          "snapshot of " + std::to_string(count) + " environments, this vector env has " +
              std::to_string(num_envs()),
          name_);
  if (!in.get_bool()) return false;
  // A failure part way leaves the vector env needing a reset.
  ready_ = false;
  load_envs(in);
  for (Episode& episode : episodes_) {
    episode.episode_return = in.get_double();
    episode.length = in.get_int64();
  }
  for (int i = 0; i < num_envs(); ++i) observe(i, result_.observations.row(i));
  ready_ = true;
  return true;
}

}  // namespace tendril::envs
