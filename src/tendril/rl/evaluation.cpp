#include "tendril/rl/evaluation.hpp"

#include <cmath>
#include <numeric>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

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

std::optional<double> EvaluationResult::success_rate() const {
  int reported = 0, successes = 0;
  for (const Info& info : final_infos) {
    if (const auto success = info.get(info_keys::kIsSuccess)) {
      ++reported;
      if (*success > 0.5) ++successes;
    }
  }
  if (reported == 0) return std::nullopt;
  return static_cast<double>(successes) / static_cast<double>(final_infos.size());
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
      if (step.terminated || step.truncated) {
        result.final_infos.push_back(std::move(step.info));
        break;
      }
      observation = std::move(step.observation);
    }
    result.returns.push_back(episode_return);
    result.lengths.push_back(length);
  }
  return result;
}

EvaluationResult evaluate_policy(const Policy& policy, envs::VecEnv& env, int episodes,
                                 bool deterministic, uint64_t seed) {
  require(episodes >= 1, "episodes must be at least 1", "rl::evaluate_policy");
  const int n = env.num_envs();
  Rng rng(seed, /*stream=*/1);
  std::vector<int> quota(n), done(n, 0);
  std::vector<double> returns(n, 0.0);
  std::vector<int64_t> lengths(n, 0);
  std::vector<EvaluationResult> per_env(n);
  for (int i = 0; i < n; ++i) quota[i] = (episodes + i) / n;
  envs::BatchMatrix observations = env.reset(seed), actions;
  auto unfinished = [&] {
    for (int i = 0; i < n; ++i) {
      if (done[i] < quota[i]) return true;
    }
    return false;
  };
  while (unfinished()) {
    policy.act(observations, deterministic, rng, actions);
    const envs::VecStep& step = env.step(actions);
    for (int i = 0; i < n; ++i) {
      if (done[i] >= quota[i]) continue;
      returns[i] += step.rewards[i];
      ++lengths[i];
      if (step.done(i)) {
        per_env[i].returns.push_back(returns[i]);
        per_env[i].lengths.push_back(lengths[i]);
        per_env[i].final_infos.push_back(step.infos[i]);
        returns[i] = 0.0;
        lengths[i] = 0;
        ++done[i];
      }
    }
    observations = step.observations;
  }
  EvaluationResult result;
  for (EvaluationResult& part : per_env) {
    result.returns.insert(result.returns.end(), part.returns.begin(), part.returns.end());
    result.lengths.insert(result.lengths.end(), part.lengths.begin(), part.lengths.end());
    for (Info& info : part.final_infos) result.final_infos.push_back(std::move(info));
  }
  return result;
}

EvaluationResult replay_actions(const std::vector<Action>& actions, Env& env, int episodes,
                                uint64_t seed) {
  require(episodes >= 1 && !actions.empty(), "needs at least one episode and one action",
          "rl::replay_actions");
  EvaluationResult result;
  for (int episode = 0; episode < episodes; ++episode) {
    if (episode == 0) {
      env.reset(seed);
    } else {
      env.reset();
    }
    double episode_return = 0.0;
    int64_t length = 0;
    for (const Action& action : actions) {
      Step step = env.step(action);
      episode_return += step.reward;
      ++length;
      if (step.terminated || step.truncated || length == static_cast<int64_t>(actions.size())) {
        result.final_infos.push_back(std::move(step.info));
        break;
      }
    }
    result.returns.push_back(episode_return);
    result.lengths.push_back(length);
  }
  return result;
}

std::vector<Action> recorded_actions(const Policy& policy, Env& env, bool deterministic,
                                     uint64_t seed) {
  Rng rng(seed, /*stream=*/1);
  std::vector<Action> actions;
  Observation observation = env.reset(seed);
  while (true) {
    actions.push_back(policy.act(observation, deterministic, rng));
    Step step = env.step(actions.back());
    if (step.terminated || step.truncated) break;
    observation = std::move(step.observation);
  }
  return actions;
}

}  // namespace tendril::rl
