#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/sma_limb/learned_reach_batch.hpp"
#include "tendril/envs/vector/batched_vec_env.hpp"

namespace tendril::envs::sma_limb {

// N SmaLimb/LearnedReach-v0 environments as one VecEnv: every step of all N is one batched call
// of the shared learned model (LearnedReachBatch), where a ThreadedVecEnv of N single envs makes
// N calls of batch 1. Behaves as that ThreadedVecEnv of `make(kId)` envs in EpisodeStatistics:
// the same time limit (truncation unless the step terminated), unseeded auto-reset, final
// observations, and "episode_return" / "episode_length" in the info of an episode's last step;
// env i's random stream is env i's of the threaded one. The registry builds it for make_vec_env
// (EnvSpec::vector_factory).
class LearnedReachVecEnv : public BatchedVecEnv {
 public:
  LearnedReachVecEnv(std::shared_ptr<DynamicsModel> model, LearnedReachOptions options,
                     int num_envs, uint64_t seed, std::optional<int64_t> max_episode_steps);
  // The parameters of LearnedReachEnv::create, one model for all envs.
  static std::unique_ptr<VecEnv> create(const Config& params, int num_envs,
                                        std::optional<int64_t> max_episode_steps);

  int num_envs() const override { return batch_.num_envs(); }
  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }

  const LearnedReachBatch& task() const { return batch_; }

 private:
  void reset_env(int i, std::optional<uint64_t> seed, Eigen::Ref<Eigen::RowVectorXf> row) override;
  void step_envs(const BatchMatrix& actions) override { batch_.step(actions); }
  Outcome outcome(int i, Eigen::Ref<Eigen::RowVectorXf> row) override;
  void save_envs(SnapshotWriter& out) const override { batch_.save_state(out); }
  void load_envs(SnapshotReader& in) override { batch_.load_state(in); }
  void observe(int i, Eigen::Ref<Eigen::RowVectorXf> row) const override;

  LearnedReachBatch batch_;
  Space observation_space_, action_space_;
  mutable Eigen::VectorXf observation_;  // one env's observation, reused
};

}  // namespace tendril::envs::sma_limb
