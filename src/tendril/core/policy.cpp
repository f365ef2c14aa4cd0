#include "tendril/core/policy.hpp"

namespace tendril {

void Policy::act(const BatchMatrix& observations, bool deterministic, Rng& rng,
                 BatchMatrix& actions) const {
  actions.resize(observations.rows(), action_space().size());
  for (Eigen::Index i = 0; i < observations.rows(); ++i) {
    const Observation observation = observations.row(i).transpose();
    actions.row(i) = act(observation, deterministic, rng).transpose();
  }
}

}  // namespace tendril
