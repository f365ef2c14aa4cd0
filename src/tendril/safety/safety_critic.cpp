#include "tendril/safety/safety_critic.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::safety {

SacSafetyCritic::SacSafetyCritic(const rl::Policy& actor, const rl::QCritics& critics)
    : actor_(actor), critics_(critics) {
  require(actor.action_space().is_box(), "a SAC safety critic needs a Box action space",
          "SacSafetyCritic");
}

double SacSafetyCritic::value(const Observation& observation, const Action& action) const {
  const Space& space = actor_.action_space();
  const auto obs_size = observation.size();
  inputs_.resize(obs_size + action.size(), 1);
  inputs_.col(0).head(obs_size) = observation;
  // The critics see actions in [−1, 1], the inverse of rl::scale_to_bounds.
  for (Eigen::Index i = 0; i < action.size(); ++i) {
    const float low = space.low()[i], high = space.high()[i];
    inputs_(obs_size + i, 0) =
        std::clamp(2.0f * (action[i] - low) / (high - low) - 1.0f, -1.0f, 1.0f);
  }
  critics_.forward(inputs_, /*target=*/false);
  return static_cast<double>(critics_.values().col(0).minCoeff());
}

Action SacSafetyCritic::safe_action(const Observation& observation) const {
  return actor_.act(observation, /*deterministic=*/true, unused_rng_);
}

DqnSafetyCritic::DqnSafetyCritic(const rl::QGreedyPolicy& q_policy) : q_policy_(q_policy) {}

const Eigen::MatrixXf& DqnSafetyCritic::q_values(const Observation& observation) const {
  q_policy_.network().forward(q_policy_.parameters(), observation, tape_);
  return tape_.output();
}

double DqnSafetyCritic::value(const Observation& observation, const Action& action) const {
  const auto index = static_cast<Eigen::Index>(action[0]);
  const Eigen::MatrixXf& q = q_values(observation);
  require(index >= 0 && index < q.rows(), "action index out of range", "DqnSafetyCritic");
  return static_cast<double>(q(index, 0));
}

Action DqnSafetyCritic::safe_action(const Observation& observation) const {
  Eigen::Index best = 0;
  q_values(observation).col(0).maxCoeff(&best);
  return Action::Constant(1, static_cast<float>(best));
}

}  // namespace tendril::safety
