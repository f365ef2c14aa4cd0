#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/vector/thread_pool.hpp"
#include "tendril/envs/vector/vec_normalize.hpp"
#include "tendril/envs/vector/vec_step.hpp"

namespace tendril::envs {

// N environments stepped in lock-step, with auto-reset (Stable-Baselines3's VecEnv semantics),
// either in the calling thread (num_threads 1) or on a persistent ThreadPool. Each environment
// is stepped by exactly one thread per call and writes only its own rows, so the threaded and
// synchronous modes give bit-identical results. An attached VecNormalize then normalizes the
// whole batch in the calling thread, so normalization keeps that guarantee.
class VecEnv {
 public:
  // All environments must have the same observation and action spaces (kind and size).
  VecEnv(std::vector<std::unique_ptr<Env>> envs, int num_threads = 1);
  // Builds num_envs environments with factory(i).
  VecEnv(int num_envs, const std::function<std::unique_ptr<Env>(int index)>& factory,
         int num_threads = 1);

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int num_threads() const { return pool_ ? pool_->num_threads() : 1; }
  // The space of the observations reset and step return (normalized ones, with a normalizer).
  const Space& observation_space() const {
    return normalizer_ ? normalizer_->observation_space() : envs_.front()->observation_space();
  }
  const Space& action_space() const { return envs_.front()->action_space(); }
  Env& env(int i) { return *envs_.at(i); }

  // Attaches SB3 VecNormalize semantics — one set of statistics for all environments — to
  // every later reset and step; the VecEnv must be reset before it steps again. Environment
  // wrappers, such as EpisodeStatistics, keep seeing raw observations and rewards.
  VecNormalize& attach_normalizer(const VecNormalize::Options& options);
  // The attached normalizer, or nullptr.
  VecNormalize* normalizer() { return normalizer_.get(); }
  const VecNormalize* normalizer() const { return normalizer_.get(); }

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
  std::unique_ptr<VecNormalize> normalizer_;
  std::vector<Action> actions_;  // per-env action buffers, reused across steps
  std::vector<std::exception_ptr> errors_;
  VecStep result_;
  bool ready_ = false;  // reset since construction, the last error or attach_normalizer
};

}  // namespace tendril::envs
