#include "tendril/envs/runner/policy_runner.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs {

namespace {

constexpr const char* kWhere = "policy runner";

void check_settings(const RunSettings& settings) {
  require((settings.episodes > 0) != (settings.steps > 0),
          "give a number of episodes or a number of steps (exactly one, positive)", kWhere);
}

void check_spaces(const Policy& policy, const Space& observations, const Space& actions) {
  require(policy.observation_space().size() == observations.size() &&
              policy.action_space().size() == actions.size(),
          "the policy acts on " + policy.observation_space().describe() + " → " +
              policy.action_space().describe() + ", the environment has " +
              observations.describe() + " → " + actions.describe(),
          kWhere);
}

}  // namespace

int64_t RunResult::finished_episodes() const {
  int64_t count = 0;
  for (const EpisodeOutcome& episode : episodes) count += episode.finished ? 1 : 0;
  return count;
}

double RunResult::mean_return() const {
  double sum = 0.0;
  for (const EpisodeOutcome& episode : episodes)
    sum += episode.finished ? episode.episode_return : 0.0;
  const int64_t count = finished_episodes();
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

double RunResult::std_return() const {
  const int64_t count = finished_episodes();
  if (count == 0) return 0.0;
  const double mean = mean_return();
  double sum = 0.0;
  for (const EpisodeOutcome& episode : episodes) {
    if (episode.finished) sum += (episode.episode_return - mean) * (episode.episode_return - mean);
  }
  return std::sqrt(sum / static_cast<double>(count));
}

double RunResult::mean_length() const {
  double sum = 0.0;
  for (const EpisodeOutcome& episode : episodes) {
    sum += episode.finished ? static_cast<double>(episode.length) : 0.0;
  }
  const int64_t count = finished_episodes();
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

std::optional<double> RunResult::success_rate() const {
  int64_t reported = 0, successes = 0;
  for (const EpisodeOutcome& episode : episodes) {
    if (!episode.finished) continue;
    if (const auto success = episode.final_info.get(info_keys::kIsSuccess)) {
      ++reported;
      successes += *success > 0.5 ? 1 : 0;
    }
  }
  if (reported == 0) return std::nullopt;
  return static_cast<double>(successes) / static_cast<double>(finished_episodes());
}

RunResult run_policy(const Policy& policy, Env& env, const RunSettings& settings,
                     const std::vector<RunObserver*>& observers) {
  check_settings(settings);
  check_spaces(policy, env.observation_space(), env.action_space());
  Rng rng(settings.seed, /*stream=*/1);
  RunResult result;
  for (int64_t k = 0; settings.steps > 0 || k < settings.episodes; ++k) {
    EpisodeOutcome outcome;
    outcome.index = k;
    outcome.seed = settings.seed + static_cast<uint64_t>(k);
    Observation observation = env.reset(outcome.seed);
    policy.begin_episode(observation);
    for (RunObserver* observer : observers) {
      observer->on_episode_start(k, outcome.seed, observation, env);
    }
    while (true) {
      if (settings.steps > 0 && result.steps == settings.steps) {
        outcome.finished = false;
        break;
      }
      const Action action = policy.act(observation, settings.deterministic, rng);
      const Step step = env.step(action);
      ++result.steps;
      outcome.episode_return += step.reward;
      for (RunObserver* observer : observers) {
        observer->on_step({k, outcome.length, observation, action, step, env});
      }
      ++outcome.length;
      if (step.terminated || step.truncated) {
        outcome.terminated = step.terminated;
        outcome.truncated = step.truncated;
        outcome.final_info = step.info;
        break;
      }
      observation = step.observation;
    }
    for (RunObserver* observer : observers) observer->on_episode_end(outcome);
    const bool budget_used = settings.steps > 0 && result.steps == settings.steps;
    if (outcome.length > 0 || outcome.finished) result.episodes.push_back(std::move(outcome));
    if (budget_used) break;
  }
  return result;
}

RunResult run_policy(const Policy& policy, VecEnv& env, const RunSettings& settings) {
  require(settings.episodes > 0 && settings.steps == 0,
          "a vector environment runs a number of whole episodes", kWhere);
  check_spaces(policy, env.observation_space(), env.action_space());
  const int n = env.num_envs();
  Rng rng(settings.seed, /*stream=*/1);
  // Env i runs episode i first; each next episode index is handed out when an env's episode
  // starts, so that its automatic reset can be seeded beforehand.
  std::vector<int64_t> running(n), following(n);
  int64_t next_index = 0;
  for (int i = 0; i < n; ++i) running[i] = next_index++;
  for (int i = 0; i < n; ++i) following[i] = next_index++;
  std::vector<EpisodeOutcome> outcomes(static_cast<std::size_t>(settings.episodes));
  int64_t remaining = settings.episodes;
  std::vector<EpisodeOutcome> current(n);
  for (int i = 0; i < n; ++i) {
    current[i].index = running[i];
    current[i].seed = settings.seed + static_cast<uint64_t>(running[i]);
  }
  // env i with seed + i: VecEnv::reset's own rule, which is the runner's for episodes 0 … n−1.
  // Environments whose episodes are not needed (index ≥ episodes) still step in lock-step; their
  // outcomes are dropped.
  BatchMatrix observations = env.reset(settings.seed);
  for (int i = 0; i < n; ++i) {
    env.seed_next_reset(i, settings.seed + static_cast<uint64_t>(following[i]));
  }
  BatchMatrix actions;
  RunResult result;
  while (remaining > 0) {
    policy.act(observations, settings.deterministic, rng, actions);
    const VecStep& step = env.step(actions);
    for (int i = 0; i < n; ++i) {
      EpisodeOutcome& episode = current[i];
      episode.episode_return += step.rewards[i];
      ++episode.length;
      ++result.steps;
      if (!step.done(i)) continue;
      episode.terminated = step.terminated[i] != 0;
      episode.truncated = step.truncated[i] != 0;
      episode.final_info = step.infos[i];
      if (episode.index < settings.episodes) {
        outcomes[static_cast<std::size_t>(episode.index)] = std::move(episode);
        --remaining;
      }
      episode = EpisodeOutcome{};
      episode.index = following[i];
      episode.seed = settings.seed + static_cast<uint64_t>(following[i]);
      following[i] = next_index++;
      env.seed_next_reset(i, settings.seed + static_cast<uint64_t>(following[i]));
    }
    observations = step.observations;
  }
  result.episodes = std::move(outcomes);
  return result;
}

}  // namespace tendril::envs
