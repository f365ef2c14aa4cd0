#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>

#include "tendril/core/rng.hpp"
#include "tendril/core/space.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/sac/sac.hpp"

namespace tendril::safety {

// A learned safety Q-function Q_s(x, u) and its greedy action argmax_u Q_s(x, u) (seed 001
// eq. 6.5's π_safe), on the environment's observations and actions (env units; a Discrete
// action is its index). V_s(x) = Q_s(x, π_safe(x)) (eq. 6.2).
class SafetyCritic {
 public:
  virtual ~SafetyCritic() = default;
  virtual double value(const Observation& observation, const Action& action) const = 0;
  virtual Action safe_action(const Observation& observation) const = 0;
  double state_value(const Observation& observation) const {
    return value(observation, safe_action(observation));
  }

  // Writes a safety critic file (an archive of kind "safety_critic", checksummed, atomic) that
  // load_safety_critic turns back into a critic with the same values and safe actions. Raises
  // Error for a critic without a file form (one scripted in code).
  void save(const std::filesystem::path& file) const;

 protected:
  // "sac" or "dqn" ("" when the critic has no file form), and the kind's own entries.
  virtual std::string kind() const { return ""; }
  virtual void write(ArchiveWriter& /*writer*/) const {}
};

// Reads a file written by SafetyCritic::save: a critic that owns what it reads. Raises Error
// naming the file on anything that is not an intact safety critic file of a known kind.
std::unique_ptr<SafetyCritic> load_safety_critic(const std::filesystem::path& file);

// A SAC safety agent: Q_s is the smaller of its twin critics (as in SAC's own targets) and the
// greedy action is the actor's mean, which the actor trains towards argmax_u Q_s. Holds a copy
// of the critics taken at construction; the actor is borrowed.
class SacSafetyCritic : public SafetyCritic {
 public:
  SacSafetyCritic(const rl::Policy& actor, const rl::QCritics& critics);
  // A view of an agent in training: before each value it takes the critics' newest parameters
  // when the agent has updated since (the filter that acts while co-training).
  explicit SacSafetyCritic(const rl::Sac& agent);
  // Owns its actor (a critic read from a file).
  SacSafetyCritic(std::unique_ptr<const rl::Policy> actor, const rl::QCritics& critics);
  double value(const Observation& observation, const Action& action) const override;
  Action safe_action(const Observation& observation) const override;

 protected:
  std::string kind() const override { return "sac"; }
  void write(ArchiveWriter& writer) const override;

 private:
  std::unique_ptr<const rl::Policy> owned_actor_;
  const rl::Policy& actor_;
  mutable rl::QCritics critics_;
  const rl::Sac* live_agent_ = nullptr;
  mutable int64_t synced_updates_ = 0;
  mutable Rng unused_rng_;
  mutable Eigen::MatrixXf inputs_;
};

// A DQN safety agent: Q_s(x, ·) is the Q-network's (QGreedyPolicy::q_values); the greedy
// action its arg max.
// Borrows the network's policy.
class DqnSafetyCritic : public SafetyCritic {
 public:
  explicit DqnSafetyCritic(const rl::QGreedyPolicy& q_policy);
  // Owns its network (a critic read from a file).
  explicit DqnSafetyCritic(std::unique_ptr<const rl::QGreedyPolicy> q_policy);
  double value(const Observation& observation, const Action& action) const override;
  Action safe_action(const Observation& observation) const override;

 protected:
  std::string kind() const override { return "dqn"; }
  void write(ArchiveWriter& writer) const override;

 private:
  std::unique_ptr<const rl::QGreedyPolicy> owned_q_policy_;
  const rl::QGreedyPolicy& q_policy_;
};

}  // namespace tendril::safety
