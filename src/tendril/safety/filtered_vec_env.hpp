#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/safety/safety_critic.hpp"

namespace tendril::safety {

// The safety filter of seed 001 eq. (6.5) as a vector-env wrapper (DESIGN.md: safety filters are
// vector wrappers). Each row's action a, proposed by whatever steps this VecEnv, is executed
// when Q_s(x, a) > ε₂ and replaced by the safety actor's action otherwise. The proposer thus
// learns in the filtered environment: the outcome of a proposal includes the correction (the
// "modified MDP" of Recovery RL, Thananjeyan et al. 2021, the thesis' ref. [60]).
//
// Used while co-training (SafetyExperiment's `training_filter`): acting through the filter lets
// the safety agent try its own actions exactly where the task agent would leave X_safe, which
// the task agent alone never shows it when the task and safety conflict (the Dubins car).
// Observations must be raw (no VecNormalize below): the critic reads them as the environment
// writes them. Borrows the critic.
class FilteredVecEnv : public envs::VecEnvWrapper {
 public:
  // The action taken where the filter intervenes: the safety policy's, e.g. its greedy action
  // (SafetyCritic::safe_action) or, while it learns, a draw from it.
  using SafeActor = std::function<Action(const Observation&)>;

  FilteredVecEnv(std::unique_ptr<envs::VecEnv> inner, const SafetyCritic& critic,
                 SafeActor safe_actor, double threshold);

  const envs::BatchMatrix& reset(std::optional<uint64_t> seed = std::nullopt) override;
  const envs::VecStep& step(const envs::BatchMatrix& actions) override;
  // Its counts and, with the environments, the observations the next decision reads, so that a
  // resumed co-training run filters exactly as the uninterrupted one.
  void save_state(SnapshotWriter& out, bool environments) const override;
  bool load_state(SnapshotReader& in) override;

  // The actions the environments executed on the last step (env units), and where the filter
  // replaced the proposal (1) or passed it (0).
  const envs::BatchMatrix& executed_actions() const { return executed_; }
  const std::vector<uint8_t>& intervened() const { return intervened_; }
  int64_t decisions() const { return decisions_; }
  int64_t interventions() const { return interventions_; }

 private:
  const SafetyCritic& critic_;
  SafeActor safe_actor_;
  double threshold_;
  envs::BatchMatrix observations_, executed_;
  std::vector<uint8_t> intervened_;
  int64_t decisions_ = 0, interventions_ = 0;
};

}  // namespace tendril::safety
