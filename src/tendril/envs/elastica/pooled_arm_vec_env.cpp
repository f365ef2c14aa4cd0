#include "tendril/envs/elastica/pooled_arm_vec_env.hpp"

#include <string>
#include <utility>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::elastica {

namespace {

constexpr const char* kWhere = "Elastica/Tracking3D-v0 (lockstep rods)";

std::vector<std::unique_ptr<Tracking3D>> build(int num_envs) {
  require(num_envs >= 1, "num_envs must be at least 1, got " + std::to_string(num_envs), kWhere);
  std::vector<std::unique_ptr<Tracking3D>> envs;
  envs.reserve(static_cast<std::size_t>(num_envs));
  for (int i = 0; i < num_envs; ++i) envs.push_back(std::make_unique<Tracking3D>());
  return envs;
}

}  // namespace

PooledArmVecEnv::PooledArmVecEnv(int num_envs, std::optional<int64_t> max_episode_steps)
    : envs_(build(num_envs)),
      pool_(envs_.front()->arm().rod, num_envs),
      max_episode_steps_(max_episode_steps),
      episodes_(static_cast<std::size_t>(num_envs)),
      next_reset_seeds_(static_cast<std::size_t>(num_envs)),
      action_(Action::Zero(action_space().size())) {
  const int size = observation_space().size();
  result_.observations = BatchMatrix::Zero(num_envs, size);
  result_.final_observations = BatchMatrix::Zero(num_envs, size);
  result_.rewards = Eigen::VectorXf::Zero(num_envs);
  result_.terminated.assign(num_envs, 0);
  result_.truncated.assign(num_envs, 0);
  result_.infos.assign(num_envs, Info{});
}

std::unique_ptr<VecEnv> PooledArmVecEnv::create(const Config& params, int num_envs,
                                                std::optional<int64_t> max_episode_steps) {
  const Tracking3D::Options options = Tracking3D::Options::from_config(params);
  if (!options.lockstep_rods) return nullptr;
  if (options.integrator != physics::RodIntegrator::kPositionVerlet) {
    throw Error(
        "lockstep_rods advances the rods by position Verlet only; drop it or use integrator: "
        "verlet",
        params.source() + ": lockstep_rods");
  }
  return std::make_unique<PooledArmVecEnv>(num_envs, max_episode_steps);
}

void PooledArmVecEnv::seed_next_reset(int env, uint64_t seed) {
  require(env >= 0 && env < num_envs(), "no environment " + std::to_string(env), kWhere);
  next_reset_seeds_[static_cast<std::size_t>(env)] = seed;
}

void PooledArmVecEnv::reset_env(int i, std::optional<uint64_t> seed) {
  Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
  result_.observations.row(i) = env.reset(seed).transpose();
  pool_.set_state(i, env.arm().rod.state());
  episodes_[static_cast<std::size_t>(i)] = Episode{};
}

const BatchMatrix& PooledArmVecEnv::reset(std::optional<uint64_t> seed) {
  next_reset_seeds_.assign(static_cast<std::size_t>(num_envs()), std::nullopt);
  ready_ = false;
  for (int i = 0; i < num_envs(); ++i) {
    reset_env(i, seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i)) : std::nullopt);
  }
  ready_ = true;
  return result_.observations;
}

const VecStep& PooledArmVecEnv::step(const BatchMatrix& actions) {
  require(ready_, "step called before reset (or after an error)", kWhere);
  if (actions.rows() != num_envs() || actions.cols() != action_space().size()) {
    throw Error("actions are " + std::to_string(actions.rows()) + " x " +
                    std::to_string(actions.cols()) + ", expected " + std::to_string(num_envs()) +
                    " x " + std::to_string(action_space().size()) + " (envs x action size)",
                kWhere);
  }
  const int substeps = envs_.front()->substeps_per_action();
  try {
    // Every action is checked (the lowest env index's error is the one raised) before any rod
    // moves.
    for (int i = 0; i < num_envs(); ++i) {
      action_ = actions.row(i).transpose();
      pool_.set_targets(i, envs_[static_cast<std::size_t>(i)]->begin_step(action_));
    }
    // Whether any rod became non-finite is each env's own outcome (is_finite below).
    static_cast<void>(pool_.advance(substeps));
    for (int i = 0; i < num_envs(); ++i) {
      Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
      physics::Rod& rod = env.arm().rod;
      pool_.get_state(i, rod.mutable_state());
      rod.state_changed();
      Step step = env.finish_step(pool_.is_finite(i));

      Episode& episode = episodes_[static_cast<std::size_t>(i)];
      episode.episode_return += step.reward;
      ++episode.length;
      const bool truncated =
          !step.terminated && max_episode_steps_ && episode.length >= *max_episode_steps_;
      result_.final_observations.row(i) = step.observation.transpose();
      result_.rewards[i] = static_cast<float>(step.reward);
      result_.terminated[i] = step.terminated ? 1 : 0;
      result_.truncated[i] = truncated ? 1 : 0;
      result_.infos[i] = std::move(step.info);
      if (step.terminated || truncated) {
        result_.infos[i].set(info_keys::kEpisodeReturn, episode.episode_return);
        result_.infos[i].set(info_keys::kEpisodeLength, static_cast<double>(episode.length));
        // Auto-reset without a seed unless seed_next_reset gave one (ThreadedVecEnv's rule).
        reset_env(i, next_reset_seeds_[static_cast<std::size_t>(i)]);
        next_reset_seeds_[static_cast<std::size_t>(i)].reset();
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

void PooledArmVecEnv::save_state(SnapshotWriter& out, bool environments) const {
  out.section(kWhere);
  out.put(static_cast<int64_t>(num_envs()));
  const bool with_envs = environments && ready_;
  out.put(with_envs);
  if (!with_envs) return;
  for (std::size_t i = 0; i < envs_.size(); ++i) {
    envs_[i]->save_state(out);
    out.put(episodes_[i].episode_return);
    out.put(episodes_[i].length);
  }
}

bool PooledArmVecEnv::load_state(SnapshotReader& in) {
  in.section(kWhere);
  const int64_t count = in.get_int64();
  require(count == num_envs(),
          "snapshot of " + std::to_string(count) + " environments, this vector env has " +
              std::to_string(num_envs()),
          kWhere);
  if (!in.get_bool()) return false;
  // Environments load one by one; a failure leaves the vector env needing a reset.
  ready_ = false;
  for (int i = 0; i < num_envs(); ++i) {
    Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
    env.load_state(in);
    Episode& episode = episodes_[static_cast<std::size_t>(i)];
    episode.episode_return = in.get_double();
    episode.length = in.get_int64();
    pool_.set_state(i, env.arm().rod.state());
  }
  ready_ = true;
  return true;
}

}  // namespace tendril::envs::elastica
