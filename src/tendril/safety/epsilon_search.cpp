#include "tendril/safety/epsilon_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"

namespace tendril::safety {

EpsilonSearchRun search_epsilon_once(const EpsilonSearchProblem& problem,
                                     const EpsilonSearchOptions& options,
                                     const Eigen::VectorXd& start) {
  Eigen::VectorXd x = start;
  double alpha = options.step_size;
  double value_prev = -std::numeric_limits<double>::infinity();
  int64_t length_prev = -1;  // −∞: no episode yet
  EpsilonSearchRun run;
  double value = problem.value(x);
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    if (std::abs(value - value_prev) <= options.tolerance) {
      run.converged = true;
      break;
    }
    value_prev = value;
    const int64_t length = problem.episode_length(x);
    const bool survived = length >= problem.max_episode_length;
    const bool survived_before = length_prev >= problem.max_episode_length;
    // Algorithm 3, lines 8–18: halve α when the outcome differs from the last one.
    if (survived != survived_before) alpha *= 0.5;
    run.trace.push_back({x, value, length, alpha});
    Eigen::VectorXd gradient = problem.gradient(x);
    if (options.unit_gradient) {
      const double norm = gradient.norm();
      gradient = norm > 0.0 ? (gradient / norm).eval() : Eigen::VectorXd::Zero(x.size());
    }
    x += (survived ? -alpha : alpha) * gradient;
    length_prev = length;
    value = problem.value(x);
  }
  run.epsilon = value;
  if (options.survivor_value) {
    for (auto step = run.trace.rbegin(); step != run.trace.rend(); ++step) {
      if (step->episode_length >= problem.max_episode_length) {
        run.epsilon = step->value;
        break;
      }
    }
  }
  return run;
}

EpsilonSearchResult search_epsilon(const EpsilonSearchProblem& problem,
                                   const EpsilonSearchOptions& options, Rng& rng) {
  require(options.restarts > 0 && options.step_size > 0.0 && options.tolerance > 0.0,
          "restarts, step size and tolerance must be positive", "search_epsilon");
  EpsilonSearchResult result;
  result.epsilon = -std::numeric_limits<double>::infinity();
  for (int restart = 0; restart < options.restarts; ++restart) {
    Eigen::VectorXd start;
    int draws = 0;
    do {
      require(draws++ < options.max_start_draws, "no start state with a positive safety value",
              "search_epsilon");
      start = problem.sample_state(rng);
    } while (problem.value(start) <= 0.0);
    result.runs.push_back(search_epsilon_once(problem, options, start));
    result.epsilon = std::max(result.epsilon, result.runs.back().epsilon);
  }
  return result;
}

Eigen::VectorXd finite_difference_gradient(
    const std::function<double(const Eigen::VectorXd&)>& value, const Eigen::VectorXd& x,
    double h) {
  Eigen::VectorXd gradient(x.size()), probe = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    probe[i] = x[i] + h;
    const double up = value(probe);
    probe[i] = x[i] - h;
    const double down = value(probe);
    probe[i] = x[i];
    gradient[i] = (up - down) / (2.0 * h);
  }
  return gradient;
}

}  // namespace tendril::safety
