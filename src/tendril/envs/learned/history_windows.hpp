#pragma once

#include <Eigen/Core>

#include "tendril/core/snapshot.hpp"
#include "tendril/envs/vector/vec_step.hpp"

namespace tendril::envs {

// The recent history of N environments driven by a learned model: for each environment a window
// of `length` rows, oldest first, row k = [x_k, u_k] (state, then the input applied from k to
// k + 1). The newest row holds the current state x_t and the input u_t about to be applied, as
// the window of seed 001's model (thesis eq. 4.3: x_{t+1} = x_t + φ(x_t, …, x_{t−n+1}, u_t)).
// All windows sit in one row-major matrix, one row of length · (state_dim + input_dim) floats per
// environment, so a batch maps onto a (N, length, state_dim + input_dim) tensor without a copy.
class HistoryWindows {
 public:
  HistoryWindows(int num_envs, int length, int state_dim, int input_dim);

  int num_envs() const { return static_cast<int>(windows_.rows()); }
  int length() const { return length_; }
  int state_dim() const { return state_dim_; }
  int input_dim() const { return input_dim_; }
  int row_size() const { return state_dim_ + input_dim_; }

  // Every row of env `env` := [state, 0]: the robot at rest in `state` with no input applied
  // (a fresh start; the history of an earlier episode is forgotten).
  void reset(int env, const Eigen::Ref<const Eigen::VectorXf>& state);
  // Env `env`'s window from recorded rows (length × row_size, oldest first).
  void set_window(int env, const Eigen::Ref<const BatchMatrix>& rows);

  // The input u_t of every env's newest row (num_envs × input_dim) or of one env.
  void set_inputs(const BatchMatrix& inputs);
  void set_input(int env, const Eigen::Ref<const Eigen::VectorXf>& input);

  // Drops every env's oldest row and appends [x_{t+1}, 0] from `next_states`
  // (num_envs × state_dim); set the new inputs before the next prediction.
  void advance(const BatchMatrix& next_states);

  // Env `env`'s newest state x_t.
  Eigen::VectorXf state(int env) const;
  // num_envs × (length · row_size), row-major.
  const BatchMatrix& windows() const { return windows_; }

  // The exact windows, for environments that save and restore their state.
  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  void check_env(int env) const;

  int length_;
  int state_dim_;
  int input_dim_;
  BatchMatrix windows_;
};

}  // namespace tendril::envs
