#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "tendril/core/env.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/envs/vector/vec_step.hpp"

namespace tendril::envs {

class VecNormalize;

// N environments stepped in lock-step with auto-reset (Stable-Baselines3's VecEnv, Gymnasium's
// VectorEnv): what every learner trains on. Implementations: ThreadedVecEnv (N `Env`s on a
// thread pool), a batched learned model; wrappers (VecEnvWrapper) change one aspect of the
// stream — VecNormalize, recorders, safety filters — without touching the others.
class VecEnv {
 public:
  virtual ~VecEnv() = default;

  virtual int num_envs() const = 0;
  // The spaces of one environment (the observations handed out, e.g. normalized ones).
  virtual const Space& observation_space() const = 0;
  virtual const Space& action_space() const = 0;

  // Resets every environment, env i with seed + i when a seed is given (otherwise each
  // continues its own random stream). Returns the (num_envs × observation size) observations;
  // the reference stays valid until the next reset or step.
  virtual const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) = 0;
  // Steps env i with row i of `actions` (num_envs × action size; a Discrete action is its
  // index), resetting every environment whose episode ended. An error of any environment is
  // rethrown (the lowest env index's if several fail); the VecEnv must then be reset. The
  // reference stays valid until the next reset or step.
  virtual const VecStep& step(const BatchMatrix& actions) = 0;
  // The next automatic reset of env `env` (after its current episode ends) uses `seed`, once;
  // later ones continue its own stream again. What the policy runner needs for "episode k
  // resets with seed + k" over several environments. Raises Error where unsupported.
  virtual void seed_next_reset(int env, uint64_t seed);

  // Whether every environment can be snapshotted (Env::supports_snapshots).
  virtual bool supports_snapshots() const = 0;
  // Writes every wrapper's own state (normalization statistics) and, when `environments` is
  // true and supports_snapshots(), every environment's state. load_state restores what was
  // written and returns whether the environments were restored; if not, they must be reset
  // before the next step. A snapshot of another vector env raises Error.
  virtual void save_state(SnapshotWriter& out, bool environments) const = 0;
  virtual bool load_state(SnapshotReader& in) = 0;

  // The VecNormalize in this chain, or nullptr: its statistics travel with trained policies.
  virtual const VecNormalize* normalizer() const { return nullptr; }
};

// A VecEnv that owns another and changes one aspect of it; the rest is passed through.
class VecEnvWrapper : public VecEnv {
 public:
  explicit VecEnvWrapper(std::unique_ptr<VecEnv> inner);

  int num_envs() const override { return inner_->num_envs(); }
  const Space& observation_space() const override { return inner_->observation_space(); }
  const Space& action_space() const override { return inner_->action_space(); }
  const BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) override {
    return inner_->reset(seed);
  }
  const VecStep& step(const BatchMatrix& actions) override { return inner_->step(actions); }
  void seed_next_reset(int env, uint64_t seed) override { inner_->seed_next_reset(env, seed); }
  bool supports_snapshots() const override { return inner_->supports_snapshots(); }
  void save_state(SnapshotWriter& out, bool environments) const override {
    inner_->save_state(out, environments);
  }
  bool load_state(SnapshotReader& in) override { return inner_->load_state(in); }
  const VecNormalize* normalizer() const override { return inner_->normalizer(); }

  VecEnv& inner() { return *inner_; }
  const VecEnv& inner() const { return *inner_; }

 protected:
  std::unique_ptr<VecEnv> inner_;
};

}  // namespace tendril::envs
