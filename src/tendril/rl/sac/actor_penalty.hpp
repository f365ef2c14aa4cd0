#pragma once

#include <Eigen/Core>

namespace tendril::rl {

// A term a constrained method adds to SAC's actor objective (eq. 12), e.g. a Lagrangian
// multiplier times a cost critic (safety/): the mean of the term over a batch of observations
// (observation size × batch) and the actor's actions for them (action size × batch, in [−1, 1]),
// returned, with its gradient with respect to those actions added to `action_gradient` (same
// shape). Called at every actor step, after the critics' step.
class ActorPenalty {
 public:
  virtual ~ActorPenalty() = default;
  virtual double add_gradient(const Eigen::MatrixXf& observations, const Eigen::MatrixXf& actions,
                              Eigen::Ref<Eigen::MatrixXf> action_gradient) = 0;
};

}  // namespace tendril::rl
