#include "tendril/envs/sma_limb/learned_reach_vec_env.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/sma_limb/learned_reach_env.hpp"

namespace tendril::envs::sma_limb {

namespace {

constexpr const char* kWhere = "SmaLimb/LearnedReach-v0 (batched)";

}  // namespace

LearnedReachVecEnv::LearnedReachVecEnv(std::shared_ptr<DynamicsModel> model,
                                       LearnedReachOptions options, int num_envs, uint64_t seed,
                                       std::optional<int64_t> max_episode_steps)
    : BatchedVecEnv(kWhere, max_episode_steps),
      batch_(std::move(model), options, num_envs, seed),
      observation_space_(batch_.observation_space()),
      action_space_(LearnedReachBatch::action_space()),
      observation_(observation_space_.size()) {
  allocate(batch_.num_envs());
}

std::unique_ptr<VecEnv> LearnedReachVecEnv::create(const Config& params, int num_envs,
                                                   std::optional<int64_t> max_episode_steps) {
  const uint64_t seed = params.get_or<uint64_t>("seed", 0);
  LearnedReachOptions options = LearnedReachOptions::from_config(params);
  return std::make_unique<LearnedReachVecEnv>(LearnedReachEnv::open_model(params), options,
                                              num_envs, seed, max_episode_steps);
}

void LearnedReachVecEnv::reset_env(int i, std::optional<uint64_t> seed,
                                   Eigen::Ref<Eigen::RowVectorXf> row) {
  batch_.reset(i, seed);
  observe(i, row);
}

BatchedVecEnv::Outcome LearnedReachVecEnv::outcome(int i, Eigen::Ref<Eigen::RowVectorXf> row) {
  observe(i, row);
  return {batch_.reward(i), batch_.terminated(i), batch_.info(i)};
}

void LearnedReachVecEnv::observe(int i, Eigen::Ref<Eigen::RowVectorXf> row) const {
  batch_.observe(i, observation_);
  row = observation_.transpose();
}

}  // namespace tendril::envs::sma_limb
