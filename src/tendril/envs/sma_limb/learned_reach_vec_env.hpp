#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/sma_limb/learned_reach_batch.hpp"
#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::envs::sma_limb {

// N SmaLimb/LearnedReach-v0 environments as one VecEnv: every step of all N is one batched call
// of the shared learned model (LearnedReachBatch), where a ThreadedVecEnv of N single envs makes
// N calls of batch 1. Behaves as that ThreadedVecEnv of `make(kId)` envs in EpisodeStatistics:
// the same time limit (truncation unless the step terminated), unseeded auto-reset, final
// observations, and "episode_return" / "episode_length" in the info of an episode's last step;
// env i's random stream is env i's of the threaded one. The registry builds it for make_vec_env
// (EnvSpec::vector_factory).
class LearnedReachVecEnv : public VecEnv {
 public:
  LearnedReachVecEnv(std::shared_ptr<DynamicsModel> model, LearnedReachOptions options,
                     int num_envs, uint64_t seed, std::optional<int64_t> max_episode_steps);
  // The parameters of LearnedReachEnv::create, one model for all envs.
  static std::unique_ptr<VecEnv> create(const Config& params, int num_envs,
                                        std::optional<int64_t> max_episode_steps);

  int num_envs() const override { return batch_.num_envs(); }
  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) override;
  const VecStep& step(const BatchMatrix& actions) override;
  void seed_next_reset(int env, uint64_t seed) override;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out, bool environments) const override;
  bool load_state(SnapshotReader& in) override;

  const LearnedReachBatch& task() const { return batch_; }

 private:
  struct Episode {
    double episode_return = 0.0;
    int64_t length = 0;
  };

  LearnedReachBatch batch_;
  std::optional<int64_t> max_episode_steps_;
  Space observation_space_, action_space_;
  std::vector<Episode> episodes_;
  VecStep result_;
  bool ready_ = false;
  std::vector<std::optional<uint64_t>> next_reset_seeds_;
};

}  // namespace tendril::envs::sma_limb
