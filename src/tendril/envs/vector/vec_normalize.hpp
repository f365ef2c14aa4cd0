#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "tendril/core/env.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/envs/vector/vec_step.hpp"
#include "tendril/envs/wrappers/running_mean_std.hpp"

namespace tendril::envs {

// Stable-Baselines3's VecNormalize (stable_baselines3/common/vec_env/vec_normalize.py): ONE set
// of running statistics for all the environments of a VecEnv, applied to whole batches after
// every environment has stepped. On each step, while training,
//
//   obs statistics ← merge(obs statistics, the batch of the N new observations),
//   R_i ← γ R_i + r_i   (per env),   return statistics ← merge(return statistics, {R_1 … R_N}),
//
// (RunningMeanStd::update_batch), then every observation row — and every final observation of
// a finished episode, with the same statistics — becomes
//
//   obs' = clip((obs − mean) / sqrt(var + ε), −clip_observation, clip_observation),
//
// every reward r' = clip(r / sqrt(var(R) + ε), −clip_reward, clip_reward), and R_i ← 0 where
// env i's episode ended. Reset merges the reset batch into the observation statistics,
// normalizes it and zeroes every R_i. Defaults: γ 0.99, ε 1e-8, both clips 10. Frozen
// (set_training(false)) it normalizes with fixed statistics and no longer accumulates R_i, as
// SB3 does.
//
// The statistics are updated in env-index order from whole batches, so they do not depend on
// how many threads stepped the environments. Wrappers inside the vector env (EpisodeStatistics)
// keep seeing raw observations and rewards. The statistics and running returns are part of
// save_state, whether or not the environments are.
class VecNormalize : public VecEnvWrapper {
 public:
  struct Options {
    bool normalize_observation = true;
    bool normalize_reward = true;
    double clip_observation = 10.0;
    double clip_reward = 10.0;
    double gamma = 0.99;  // discount of the return R whose standard deviation scales rewards
    double epsilon = 1e-8;
  };

  // Normalizing observations needs a Box observation space; raises Error on bad options.
  VecNormalize(std::unique_ptr<VecEnv> inner, Options options);

  const Options& options() const { return options_; }
  // The space of the observations handed out: Box(size, [−clip_observation, clip_observation])
  // when they are normalized, otherwise the environments' own space.
  const Space& observation_space() const override { return observation_space_; }

  // SB3's VecNormalize.reset and step_wait: the inner batch, normalized.
  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) override;
  const VecStep& step(const BatchMatrix& actions) override;

  void save_state(SnapshotWriter& out, bool environments) const override;
  bool load_state(SnapshotReader& in) override;
  const VecNormalize* normalizer() const override { return this; }

  bool training() const { return training_; }
  void set_training(bool training) { training_ = training; }

  const RunningMeanStd& observation_statistics() const { return observation_statistics_; }
  const RunningMeanStd& return_statistics() const { return return_statistics_; }
  const Eigen::VectorXd& returns() const { return returns_; }  // R_i, one per env

  // Install saved state (a checkpoint's). Each raises Error, changing nothing, if the sizes do
  // not match (observation size; one return component and num_envs returns).
  void set_observation_statistics(const RunningMeanStd& statistics);
  void set_return_state(const RunningMeanStd& statistics, const Eigen::VectorXd& returns);

 private:
  void normalize_rows(BatchMatrix& rows) const;
  void normalize_reset(BatchMatrix& observations);
  void normalize_step(VecStep& step);

  Options options_;
  Space observation_space_;
  RunningMeanStd observation_statistics_;
  RunningMeanStd return_statistics_{1};
  Eigen::VectorXd returns_;
  Eigen::MatrixXd batch_;     // the observation batch in double precision, reused across steps
  BatchMatrix observations_;  // the normalized reset batch
  VecStep result_;            // the normalized step
  bool training_ = true;
};

}  // namespace tendril::envs
