#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/core/config.hpp"
#include "tendril/nn/adam.hpp"
#include "tendril/rl/observer.hpp"
#include "tendril/rl/sac/actor_penalty.hpp"
#include "tendril/safety/cost_critic.hpp"

namespace tendril::safety {

// How the multiplier ν of LagrangianPenalty moves.
struct MultiplierSettings {
  enum class Kind {
    kLearned,   // Lagrangian relaxation (LR): dual gradient steps on log ν
    kScheduled  // RSPO: ν falls linearly from `start` to `end` over the training budget
  };
  Kind kind = Kind::kLearned;
  double initial = 1.0;         // ν₀ (LR)
  double learning_rate = 1e-3;  // of log ν (LR)
  double start = 100.0;         // ν at the first step (RSPO)
  double end = 0.0;             // ν at the last step (RSPO)

  // `method` "lagrangian" or "rspo"; reads the keys of that kind from `config`.
  static MultiplierSettings from_config(const std::string& method, const Config& config);
};

// The constrained baselines of seed 001 Table 6.1, as the Recovery RL paper (Thananjeyan et al.
// 2021, the thesis' ref. [60]) defines and runs them: SAC whose actor minimises
//
//   E_s[ α log π(a|s) − Q(s, a) + ν (Q_risk(s, a) − ε_risk) ],   a ~ π(·|s),
//
// with the cost critic Q_risk (CostCritic) and the cost limit ε_risk. Lagrangian relaxation (LR)
// learns ν by dual descent on log ν with the gradient (ε_risk − E_s[Q_risk(s, a)]): ν grows while
// the policy's risk exceeds the limit and shrinks below it. RSPO (Risk Sensitive Policy
// Optimization) instead anneals ν linearly to `end`, strict early in training and permissive
// late. Install with Sac::set_actor_penalty and observe the task agent's steps (for RSPO's
// schedule). Borrows the critic.
class LagrangianPenalty : public rl::ActorPenalty, public rl::Observer {
 public:
  LagrangianPenalty(CostCritic& critic, double cost_limit, const MultiplierSettings& multiplier,
                    int64_t total_timesteps);

  double add_gradient(const Eigen::MatrixXf& observations, const Eigen::MatrixXf& actions,
                      Eigen::Ref<Eigen::MatrixXf> action_gradient) override;
  void on_step(const rl::StepEvent& event) override { timesteps_ = event.timesteps; }

  double multiplier() const;
  double last_cost_value() const { return last_cost_value_; }  // E_s[Q_risk(s, π(s))]

  // Its state — the step count, log ν and its optimizer, the last cost value — in and out of a
  // checkpoint under `prefix` (as CostCritic's).
  void save(ArchiveWriter& writer, const std::string& prefix) const;
  std::function<void()> prepare_load(const ArchiveReader& reader, const std::string& prefix);

 private:
  CostCritic& critic_;
  double cost_limit_;
  MultiplierSettings settings_;
  int64_t total_timesteps_;
  int64_t timesteps_ = 0;
  Eigen::VectorXf log_multiplier_;  // one entry: log ν (LR)
  nn::Adam optimizer_;
  double last_cost_value_ = 0.0;
};

}  // namespace tendril::safety
