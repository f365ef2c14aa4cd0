#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/vector/thread_pool.hpp"

namespace tendril::envs {

// Row-major, one row per environment: the whole batch is one contiguous float buffer that maps
// onto a (num_envs × size) tensor or NumPy array without a copy.
using BatchMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The result of stepping every environment once.
struct VecStep {
  // Row i: env i's next observation. Where env i's episode ended on this step, the environment
  // has already been reset and this is the first observation of its next episode.
  BatchMatrix observations;
  // Row i: the observation that followed this step within env i's own episode — equal to
  // `observations` row i unless the episode ended, in which case it is the episode's final
  // observation (bootstrap from it through a truncation).
  BatchMatrix final_observations;
  Eigen::VectorXf rewards;
  std::vector<uint8_t> terminated;  // 1 where the task ended (do not bootstrap)
  std::vector<uint8_t> truncated;   // 1 where a time limit cut the episode (bootstrap)
  std::vector<Info> infos;          // env i's info for this step (episode statistics included)

  bool done(int i) const { return terminated[i] != 0 || truncated[i] != 0; }
};

// N environments stepped in lock-step, with auto-reset (Stable-Baselines3's VecEnv semantics),
// either in the calling thread (num_threads 1) or on a persistent ThreadPool. Each environment
// is stepped by exactly one thread per call and writes only its own rows, so the threaded and
// synchronous modes give bit-identical results.
class VecEnv {
 public:
  // All environments must have the same observation and action spaces (kind and size).
  VecEnv(std::vector<std::unique_ptr<Env>> envs, int num_threads = 1);
  // Builds num_envs environments with factory(i).
  VecEnv(int num_envs, const std::function<std::unique_ptr<Env>(int index)>& factory,
         int num_threads = 1);

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int num_threads() const { return pool_ ? pool_->num_threads() : 1; }
  const Space& observation_space() const { return envs_.front()->observation_space(); }
  const Space& action_space() const { return envs_.front()->action_space(); }
  Env& env(int i) { return *envs_.at(i); }

  // Resets every environment, env i with seed + i when a seed is given (otherwise each continues
  // its own random stream). Returns the (num_envs × observation size) observations; the
  // reference stays valid until the next reset or step.
  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt);

  // Steps env i with row i of `actions` (num_envs × action size; a Discrete action is its index),
  // resetting every environment whose episode ended. An error raised by an environment, in any
  // thread, is rethrown here unchanged (that of the lowest env index if several fail); the
  // VecEnv must then be reset before stepping again. The reference stays valid until the next
  // reset or step.
  const VecStep& step(const BatchMatrix& actions);

 private:
  void for_each_env(const std::function<void(int)>& task);
  void step_one(int i);

  std::vector<std::unique_ptr<Env>> envs_;
  std::unique_ptr<ThreadPool> pool_;
  std::vector<Action> actions_;  // per-env action buffers, reused across steps
  std::vector<std::exception_ptr> errors_;
  VecStep result_;
  bool ready_ = false;  // reset since construction or since the last error
};

}  // namespace tendril::envs
