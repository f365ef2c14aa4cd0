#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/sma_limb/learned_reach_task.hpp"
#include "tendril/envs/sma_limb/power_proxy.hpp"

namespace tendril::envs::sma_limb {

// N reaching tasks of seed 001 (thesis §5.1.1) inside one learned model of the limb: each
// environment keeps its window of the past states and throttles (HistoryWindows), its goal,
// power proxy, previous throttles and step count; one step of all N is one batched model call.
// Shared by SmaLimb/LearnedReach-v0 (N = 1) and its batched vector env.
//
// Observation of env i (thesis order): [θx, θy, θ̇x, θ̇y, u_x, u_y, gθx, gθy, gθ̇x, gθ̇y] and,
// with the power proxy on, [p+x, p−x, p+y, p−y] after them (14 or 10 values); u is the
// previous step's throttles, g the goal. With `history` = H > 0, H rows [x_k, u_{k−1}] follow,
// oldest first, the newest being [x_t, u_{t−1}] (read from the model's window; the input before
// the window's oldest row reads 0).
// Resets (thesis "Terminating Conditions & Resets"): a half reset draws a new goal and keeps the
// state and the history, so the model carries what happened across episodes; a full reset also
// draws a new start state (at rest in its window: every row [x, 0]) — the limb after a long
// cool-down. A reset is full with probability full_reset_probability, and always on the first
// reset, on a seeded reset, and after an episode that left the bounds or the model's range
// (non-finite prediction): its state cannot start another episode. The power proxy restarts at
// 0 on every reset (the author's code).
class LearnedReachBatch {
 public:
  // The model must predict 4 states (θx, θy, θ̇x, θ̇y) from 2 inputs (u_x, u_y). Env i's random
  // stream starts from Rng(seed + i).
  LearnedReachBatch(std::shared_ptr<DynamicsModel> model, LearnedReachOptions options, int num_envs,
                    uint64_t seed);

  int num_envs() const { return static_cast<int>(tasks_.size()); }
  int observation_size() const { return (options_.power_proxy ? 14 : 10) + 6 * options_.history; }
  const LearnedReachOptions& options() const { return options_; }
  // Observation space (states within ±bound until an episode ends there) and the action space
  // Box(2, [−10, 10]).
  Space observation_space() const;
  static Space action_space();

  // Resets env `env` as described above; `seed` restarts its random stream and forces a full
  // reset.
  void reset(int env, std::optional<uint64_t> seed = std::nullopt);
  // Steps every env: row i of `actions` (N × 2) are env i's throttles, rounded to whole
  // throttles (when integer_throttles) and limited to ±10 as the firmware does. Raises Error on
  // a wrong size or a non-finite action.
  void step(const BatchMatrix& actions);

  // Env `env`'s observation into `out` (observation_size values).
  void observe(int env, Eigen::Ref<Eigen::VectorXf> out) const;
  double reward(int env) const { return tasks_[env].reward; }
  bool terminated(int env) const { return tasks_[env].terminated; }
  // "distance_deg" (‖θ − θ_goal‖), "tolerance_deg", "is_success", "out_of_bounds", "nan",
  // "full_reset" (1 when the episode began with a full reset), "u_x", "u_y".
  const Info& info(int env) const { return tasks_[env].info; }

  Eigen::Vector4d state(int env) const;
  const Eigen::Vector4d& goal(int env) const { return tasks_[env].goal; }
  void set_goal(int env, const Eigen::Vector4d& goal);
  const PowerProxy& power(int env) const { return tasks_[env].power; }
  int64_t simulated_steps(int env) const { return tasks_[env].simulated_steps; }
  double tolerance(int env) const;
  const HistoryWindows& windows() const { return windows_; }

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  struct Task {
    Rng rng;
    Eigen::Vector4d goal = Eigen::Vector4d::Zero();
    PowerProxy power;
    Eigen::Vector2d throttles = Eigen::Vector2d::Zero();  // applied on the latest step
    int64_t simulated_steps = 0;                          // over every episode, never reset
    bool needs_full_reset = true;
    bool full_reset = false;
    double reward = 0.0;
    bool terminated = false;
    Info info;
  };

  void check_env(int env) const;
  void draw_goal(Task& task);
  void start_info(Task& task);

  std::shared_ptr<DynamicsModel> model_;
  LearnedReachOptions options_;
  HistoryWindows windows_;
  std::vector<Task> tasks_;
  BatchMatrix inputs_, next_states_;
};

}  // namespace tendril::envs::sma_limb
