#include "tendril/rl/evaluation.hpp"

#include <cmath>
#include <numeric>

#include "tendril/core/error.hpp"

namespace tendril::rl {

double EvaluationResult::mean_return() const {
  if (returns.empty()) return 0.0;
  return std::accumulate(returns.begin(), returns.end(), 0.0) / static_cast<double>(returns.size());
}

double EvaluationResult::std_return() const {
  if (returns.empty()) return 0.0;
  const double mean = mean_return();
  double sum = 0.0;
  for (double r : returns) sum += (r - mean) * (r - mean);
  return std::sqrt(sum / static_cast<double>(returns.size()));
}

EvaluationResult evaluate_policy(const Policy& policy, Env& env, int episodes, bool deterministic,
                                 uint64_t seed) {
  require(episodes >= 1, "episodes must be at least 1", "rl::evaluate_policy");
  Rng rng(seed, /*stream=*/1);
  EvaluationResult result;
  for (int episode = 0; episode < episodes; ++episode) {
    Observation observation = episode == 0 ? env.reset(seed) : env.reset();
    double episode_return = 0.0;
    int64_t length = 0;
    while (true) {
      Step step = env.step(policy.act(observation, deterministic, rng));
      episode_return += step.reward;
      ++length;
      if (step.terminated || step.truncated) break;
      observation = std::move(step.observation);
    }
    result.returns.push_back(episode_return);
    result.lengths.push_back(length);
  }
  return result;
}

}  // namespace tendril::rl
