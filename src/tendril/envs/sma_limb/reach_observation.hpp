#pragma once

#include <Eigen/Core>

#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/sma_limb/learned_reach_task.hpp"
#include "tendril/envs/sma_limb/power_proxy.hpp"

namespace tendril::envs::sma_limb {

// The observation of seed 001's reaching task (thesis §5.1.1; layout in LearnedReachBatch):
// [θx, θy, θ̇x, θ̇y, u_x, u_y, gθx, gθy, gθ̇x, gθ̇y], then [p+x, p−x, p+y, p−y] when `power` is
// given, then `history` rows [x_k, u_{k−1}] from env `env`'s window, oldest first, the newest
// being [x_t, u_{t−1}] (the input before the window's oldest row reads 0). Non-finite values
// (a model that left its range) read 0. `out` has 10 or 14 + 6 · history values.
void write_reach_observation(const HistoryWindows& windows, int env,
                             const Eigen::Vector2d& throttles, const Eigen::Vector4d& goal,
                             const PowerProxy* power, int history, Eigen::Ref<Eigen::VectorXf> out);

// The same observation of a limb under closed-loop control — the twin or the robot, read through
// its sensor (thesis §5.2, Fig. 5.4: "cached and pre-processed to match the observation format
// used during training") — so that a policy trained in SmaLimb/LearnedReach-v0 can drive it:
// the states read and the throttles applied go into a window of `options.history` rows (at
// least one), the throttles into the power proxy when `options.power_proxy`. The observation is
// the env's exactly when the history spans the model's whole window (seed 001: 100 of 100 rows):
// then the oldest row's previous throttles read 0 in both.
class ReachObserver {
 public:
  explicit ReachObserver(const LearnedReachOptions& options);

  int observation_size() const { return (options_.power_proxy ? 14 : 10) + 6 * options_.history; }
  // A fresh start at `state` [θx, θy, θ̇x, θ̇y]: every row of the window [state, 0], power 0, no
  // throttles yet (a full reset of the task).
  void reset(const Eigen::Vector4d& state);
  // The throttles about to be applied from the current state.
  void apply(const Eigen::Vector2d& throttles);
  // The state they led to.
  void reached(const Eigen::Vector4d& state);
  // The observation for a goal [θx, θy, θ̇x, θ̇y].
  void observe(const Eigen::Vector4d& goal, Eigen::Ref<Eigen::VectorXf> out) const;

 private:
  LearnedReachOptions options_;
  HistoryWindows windows_;
  PowerProxy power_;
  Eigen::Vector2d throttles_ = Eigen::Vector2d::Zero();
  BatchMatrix next_;
};

}  // namespace tendril::envs::sma_limb
