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
    : BatchedVecEnv(kWhere, max_episode_steps),
      envs_(build(num_envs)),
      pool_(envs_.front()->arm().rod, num_envs),
      action_(Action::Zero(action_space().size())),
      last_observations_(BatchMatrix::Zero(num_envs, observation_space().size())) {
  allocate(num_envs);
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

void PooledArmVecEnv::reset_env(int i, std::optional<uint64_t> seed,
                                Eigen::Ref<Eigen::RowVectorXf> row) {
  Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
  last_observations_.row(i) = env.reset(seed).transpose();
  row = last_observations_.row(i);
  pool_.set_state(i, env.arm().rod.state());
}

void PooledArmVecEnv::step_envs(const BatchMatrix& actions) {
  // Every action is checked (the lowest env index's error is the one raised) before any rod
  // moves.
  for (int i = 0; i < num_envs(); ++i) {
    action_ = actions.row(i).transpose();
    pool_.set_targets(i, envs_[static_cast<std::size_t>(i)]->begin_step(action_));
  }
  // Whether any rod became non-finite is each env's own outcome (is_finite in outcome).
  static_cast<void>(pool_.advance(envs_.front()->substeps_per_action()));
}

BatchedVecEnv::Outcome PooledArmVecEnv::outcome(int i, Eigen::Ref<Eigen::RowVectorXf> row) {
  Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
  physics::Rod& rod = env.arm().rod;
  pool_.get_state(i, rod.mutable_state());
  rod.state_changed();
  Step step = env.finish_step(pool_.is_finite(i));
  last_observations_.row(i) = step.observation.transpose();
  row = last_observations_.row(i);
  return {step.reward, step.terminated, std::move(step.info)};
}

void PooledArmVecEnv::save_envs(SnapshotWriter& out) const {
  for (std::size_t i = 0; i < envs_.size(); ++i) {
    envs_[i]->save_state(out);
    out.put_matrix(last_observations_.row(static_cast<Eigen::Index>(i)));
  }
}

void PooledArmVecEnv::load_envs(SnapshotReader& in) {
  Eigen::RowVectorXf row(observation_space().size());
  for (int i = 0; i < num_envs(); ++i) {
    Tracking3D& env = *envs_[static_cast<std::size_t>(i)];
    env.load_state(in);
    in.get_matrix(row);
    last_observations_.row(i) = row;
    pool_.set_state(i, env.arm().rod.state());
  }
}

void PooledArmVecEnv::observe(int i, Eigen::Ref<Eigen::RowVectorXf> row) const {
  row = last_observations_.row(i);
}

}  // namespace tendril::envs::elastica
