#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/tracking_3d.hpp"
#include "tendril/envs/vector/batched_vec_env.hpp"
#include "tendril/physics/rod/rod_pool.hpp"

namespace tendril::envs::elastica {

// N Elastica/Tracking3D-v0 environments as one VecEnv whose arms' rods advance together in one
// RodPool (vectorized across rods, blocks of kRodLanes), where a ThreadedVecEnv advances N Rods
// one after the other. Each env keeps its own Tracking3D for the task (target motion, observation,
// reward, NaN handling); a step is, per env, ElasticaArmEnv::begin_step and the pool's muscle
// targets, then one RodPool::advance for all, then per env the pool's rod state copied into the
// env's rod and ElasticaArmEnv::finish_step. As the pool's rods are a lone Rod's bit for bit,
// this behaves exactly as the ThreadedVecEnv of N `make(kId)` envs in EpisodeStatistics: the
// same observations, rewards, flags and infos, the time limit (truncation unless the step
// terminated), unseeded auto-reset, final observations, "episode_return" / "episode_length" in
// the info of an episode's last step and seed_next_reset; env i's random stream is env i's of
// the threaded one. Snapshots (every env's own, its episode totals) restore a run exactly; they
// are this class's own, not loadable into a ThreadedVecEnv or back.
//
// Cost: it pays once the envs fill a block of rods — about 1.5× the env steps per second per
// core of the threaded one at n_envs = 8 and 64, but 0.25× for one env, whose block of eight
// lanes carries one rod (bench/pooled_arm_env_bench.cpp, docs/benchmarks.md).
//
// Position Verlet only: an implicit integrator (backward_euler, bdf2) is refused with an Error,
// as RodPool refuses contact and rate-limited muscles — so the obstacle cases 3 and 4 have no
// pooled vector env. The registry builds it for make_vector when the env parameter
// lockstep_rods is true (EnvSpec::vector_factory); make_vec_env uses it when no per-env
// wrappers are listed.
class PooledArmVecEnv : public BatchedVecEnv {
 public:
  static constexpr const char* kId = "Elastica/Tracking3D-v0";

  PooledArmVecEnv(int num_envs, std::optional<int64_t> max_episode_steps);
  // The vector factory of Elastica/Tracking3D-v0: reads Tracking3D's parameters and returns
  // nullptr (a ThreadedVecEnv of single envs is built instead) unless lockstep_rods is true.
  // Raises Error for lockstep_rods with an implicit integrator.
  static std::unique_ptr<VecEnv> create(const Config& params, int num_envs,
                                        std::optional<int64_t> max_episode_steps);

  int num_envs() const override { return static_cast<int>(envs_.size()); }
  const Space& observation_space() const override { return envs_.front()->observation_space(); }
  const Space& action_space() const override { return envs_.front()->action_space(); }

  // Env i's task and arm (its rod holds the pool's state of rod i after every step).
  const Tracking3D& env(int i) const { return *envs_.at(static_cast<std::size_t>(i)); }

 private:
  // Resets env i and puts its rod's state into the pool.
  void reset_env(int i, std::optional<uint64_t> seed, Eigen::Ref<Eigen::RowVectorXf> row) override;
  void step_envs(const BatchMatrix& actions) override;
  Outcome outcome(int i, Eigen::Ref<Eigen::RowVectorXf> row) override;
  void save_envs(SnapshotWriter& out) const override;
  void load_envs(SnapshotReader& in) override;
  void observe(int i, Eigen::Ref<Eigen::RowVectorXf> row) const override;

  std::vector<std::unique_ptr<Tracking3D>> envs_;
  physics::RodPool pool_;
  Action action_;  // one row of the actions, reused
  // The observation each env's last reset or step gave (what load_envs restores the rows from).
  BatchMatrix last_observations_;
};

}  // namespace tendril::envs::elastica
