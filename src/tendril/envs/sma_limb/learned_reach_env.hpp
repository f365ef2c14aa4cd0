#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/sma_limb/learned_reach_batch.hpp"

namespace tendril::envs::sma_limb {

// SmaLimb/LearnedReach-v0: seed 001's reaching task inside a learned model of the limb (thesis
// §5.1.1, Fig. 5.1) — drive the bend angles to a random goal within the goal tolerance. The
// model is any envs::DynamicsModel of [θx, θy, θ̇x, θ̇y] under (u_x, u_y); one step is one of the
// model's sampling periods. Observation, reward, terminations and resets: LearnedReachBatch and
// reach_outcome. Episodes last at most 250 steps (the registry's time limit).
//
// Parameters (`env.params`): model (a model file or a `tendril model fit` run directory,
// opened through install_dynamics_model_loader; default: LinearLimbModel, a torch-free stand-in
// for tests and smoke runs, not the limb), seed (default 0), and the options of
// LearnedReachOptions::from_config.
class LearnedReachEnv : public Env {
 public:
  static constexpr const char* kId = "SmaLimb/LearnedReach-v0";
  static constexpr int kEpisodeSteps = 250;

  LearnedReachEnv(std::shared_ptr<DynamicsModel> model, LearnedReachOptions options, uint64_t seed);
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();
  // The model `params.model` names, through the installed loader (LinearLimbModel without one).
  static std::shared_ptr<DynamicsModel> open_model(const Config& params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  bool describe_scene(Scene& scene) const override;

  LearnedReachBatch& task() { return batch_; }
  const LearnedReachBatch& task() const { return batch_; }

 private:
  Observation observe() const;

  LearnedReachBatch batch_;
  Space observation_space_, action_space_;
  BatchMatrix action_;
  bool needs_reset_ = true;
};

}  // namespace tendril::envs::sma_limb
