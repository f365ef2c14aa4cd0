#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/vector/thread_pool.hpp"
#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::envs {

// N `Env`s stepped in lock-step, either in the calling thread (num_threads 1) or on a
// persistent ThreadPool. Each environment is stepped by exactly one thread per call and writes
// only its own rows, so the threaded and synchronous modes give bit-identical results.
class ThreadedVecEnv : public VecEnv {
 public:
  // All environments must have the same observation and action spaces (kind and size).
  ThreadedVecEnv(std::vector<std::unique_ptr<Env>> envs, int num_threads = 1);
  // Builds num_envs environments with factory(i).
  ThreadedVecEnv(int num_envs, const std::function<std::unique_ptr<Env>(int index)>& factory,
                 int num_threads = 1);

  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int num_threads() const { return pool_ ? pool_->num_threads() : 1; }
  const Space& observation_space() const override { return envs_.front()->observation_space(); }
  const Space& action_space() const override { return envs_.front()->action_space(); }
  Env& env(int i) { return *envs_.at(i); }

  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) override;
  const VecStep& step(const BatchMatrix& actions) override;
  void seed_next_reset(int env, uint64_t seed) override;

  bool supports_snapshots() const override;
  void save_state(SnapshotWriter& out, bool environments) const override;
  bool load_state(SnapshotReader& in) override;

 private:
  void for_each_env(const std::function<void(int)>& task);
  void step_one(int i);

  std::vector<std::unique_ptr<Env>> envs_;
  std::unique_ptr<ThreadPool> pool_;
  std::vector<Action> actions_;  // per-env action buffers, reused across steps
  std::vector<std::exception_ptr> errors_;
  std::vector<std::optional<uint64_t>> next_reset_seeds_;  // seed_next_reset's, per env
  VecStep result_;
  bool ready_ = false;  // reset since construction or the last error
};

}  // namespace tendril::envs
