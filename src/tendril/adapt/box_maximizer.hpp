#pragma once

#include <Eigen/Core>
#include <functional>

namespace tendril::adapt {

// A smooth function to maximise: returns f(x) and writes ∇f(x) into `gradient` (sized like x).
using SmoothObjective = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)>;

struct BoxMaximum {
  Eigen::VectorXd point;
  double value = 0.0;
  int evaluations = 0;
};

// Maximises `objective` over the box [lower, upper] by bound-constrained L-BFGS (NLopt's
// LD_LBFGS, Liu & Nocedal 1989 as implemented by Lukšan) from `start`, which is clamped into
// the box. Stops after `max_evaluations` evaluations or when an iteration changes f by less than
// `relative_tolerance`·|f|. Returns the best point evaluated, whatever status NLopt ends with
// (a round-off-limited stop still improves on the start). An exception the objective throws is
// rethrown here.
BoxMaximum maximize_in_box(const SmoothObjective& objective, const Eigen::VectorXd& lower,
                           const Eigen::VectorXd& upper, const Eigen::VectorXd& start,
                           int max_evaluations, double relative_tolerance);

}  // namespace tendril::adapt
