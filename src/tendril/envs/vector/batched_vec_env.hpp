#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::envs {

// A vector env whose N environments step together in one computation (a learned model called
// once for all of them, a pool of rods advanced in lockstep). It does, once for all such
// envs, what a vector env owes its caller beyond the stepping: the actions' shape, time-limit
// truncation, the finished episode's return and length in its last info, the automatic reset
// (unseeded unless seed_next_reset gave a seed, as ThreadedVecEnv does), final observations, and
// the snapshot's framing. A subclass resets one environment, steps them all, and reports each
// one's outcome.
//
// After any error in reset or step the vector env must be reset.
class BatchedVecEnv : public VecEnv {
 public:
  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) final;
  const VecStep& step(const BatchMatrix& actions) final;
  void seed_next_reset(int env, uint64_t seed) final;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out, bool environments) const final;
  bool load_state(SnapshotReader& in) final;

 protected:
  // `name` names the env in errors and snapshot sections.
  BatchedVecEnv(std::string name, std::optional<int64_t> max_episode_steps);
  // Sizes the buffers; called by the subclass's constructor once its spaces exist.
  void allocate(int num_envs);

  // What one env's last step gave.
  struct Outcome {
    double reward = 0.0;
    bool terminated = false;
    Info info;
  };

  // Resets env i (seeded, or continuing its own stream) and writes its first observation.
  virtual void reset_env(int i, std::optional<uint64_t> seed,
                         Eigen::Ref<Eigen::RowVectorXf> row) = 0;
  // Steps every env with its row of `actions` (shape already checked).
  virtual void step_envs(const BatchMatrix& actions) = 0;
  // Env i's outcome of the last step_envs, its observation written into `row`.
  virtual Outcome outcome(int i, Eigen::Ref<Eigen::RowVectorXf> row) = 0;
  // The environments' own state (all of them), and reading it back; after load_envs, each env's
  // current observation is written by observe.
  virtual void save_envs(SnapshotWriter& out) const = 0;
  virtual void load_envs(SnapshotReader& in) = 0;
  virtual void observe(int i, Eigen::Ref<Eigen::RowVectorXf> row) const = 0;

  const std::string& name() const { return name_; }

 private:
  struct Episode {
    double episode_return = 0.0;
    int64_t length = 0;
  };

  std::string name_;
  std::optional<int64_t> max_episode_steps_;
  std::vector<Episode> episodes_;
  std::vector<std::optional<uint64_t>> next_reset_seeds_;
  VecStep result_;
  bool ready_ = false;
};

}  // namespace tendril::envs
