#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril::safety {

// What Algorithm 3 of seed 001 (§6.3.2, gradient-based search for ε₂) needs, over states x of
// the caller's choosing (e.g. normalized observations):
struct EpsilonSearchProblem {
  std::function<double(const Eigen::VectorXd&)> value;              // V_safe(x)
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> gradient;  // ∇V_safe(x)
  // Length of one episode of the safety policy started at x (T_max when it survived).
  std::function<int64_t(const Eigen::VectorXd&)> episode_length;
  std::function<Eigen::VectorXd(Rng&)> sample_state;  // a random x (redrawn until V(x) > 0)
  int64_t max_episode_length = 0;                     // T_max
};

// α, δ and the restarts are not given by the thesis; these defaults are the labelled
// suggestions of the seed's extraction (α₀ = 0.1 in normalized units, δ = 0.1, 20 restarts).
struct EpsilonSearchOptions {
  double step_size = 0.1;    // α₀
  double tolerance = 0.1;    // δ on |V(x) − V_prev|
  int restarts = 20;         // the maximum over restarts is taken
  int max_iterations = 200;  // per restart, a guard the algorithm box does not have
  int max_start_draws = 10000;
  // Move by α along the gradient's direction, x ∓ α ∇V/‖∇V‖, instead of the box's x ∓ α ∇V, so
  // that α is a length in state units whatever the value's scale: a learned V falls by about
  // 1/(1 − γ) across the boundary of X_unsafe, and a raw gradient step would leave the state
  // space. (No move where ∇V = 0.)
  bool unit_gradient = false;
  // Report V at the last state whose rollout survived (the safe side of the boundary the search
  // brackets) instead of V at the final state. Where V drops to the unsafe value −1/(1 − γ)
  // across the boundary — every safe state recoverable, as for a car that can stop — the final
  // state lies on either side, and on the unsafe side V says nothing about the boundary.
  bool survivor_value = false;
};

// One iteration of a search: the state, its value, the episode length from it, and the step
// size used for the move that followed.
struct EpsilonSearchStep {
  Eigen::VectorXd state;
  double value = 0.0;
  int64_t episode_length = 0;
  double step_size = 0.0;
};

struct EpsilonSearchRun {
  double epsilon = 0.0;  // V_safe at the final state (or the last survivor, survivor_value)
  std::vector<EpsilonSearchStep> trace;
  bool converged = false;  // |V − V_prev| ≤ δ before max_iterations
};

// Algorithm 3 from one start x (V(x) > 0): a survived episode moves x down the gradient (the
// boundary is lower), a failed one up; α halves whenever the outcome flips (including the
// first survival, since l_prev starts at −∞); stops when V changes by at most δ.
EpsilonSearchRun search_epsilon_once(const EpsilonSearchProblem& problem,
                                     const EpsilonSearchOptions& options,
                                     const Eigen::VectorXd& start);

struct EpsilonSearchResult {
  double epsilon = 0.0;  // the maximum over restarts
  std::vector<EpsilonSearchRun> runs;
};

// Algorithm 3 with `options.restarts` random starts; ε₂ = the largest result.
EpsilonSearchResult search_epsilon(const EpsilonSearchProblem& problem,
                                   const EpsilonSearchOptions& options, Rng& rng);

// Central finite differences of `value` with step h per coordinate (for a value that has no
// gradient of its own, e.g. through an actor).
Eigen::VectorXd finite_difference_gradient(
    const std::function<double(const Eigen::VectorXd&)>& value, const Eigen::VectorXd& x, double h);

}  // namespace tendril::safety
