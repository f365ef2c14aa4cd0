#include "tendril/rl/open_loop.hpp"

#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::rl {

envs::RunResult replay_actions(const std::vector<Action>& actions, Env& env, int episodes,
                               uint64_t seed) {
  require(episodes >= 1 && !actions.empty(), "needs at least one episode and one action",
          "rl::replay_actions");
  envs::RunResult result;
  for (int k = 0; k < episodes; ++k) {
    envs::EpisodeOutcome outcome;
    outcome.index = k;
    outcome.seed = seed + static_cast<uint64_t>(k);
    env.reset(outcome.seed);
    for (const Action& action : actions) {
      Step step = env.step(action);
      outcome.episode_return += step.reward;
      ++outcome.length;
      ++result.steps;
      if (step.terminated || step.truncated ||
          outcome.length == static_cast<int64_t>(actions.size())) {
        outcome.terminated = step.terminated;
        outcome.truncated = step.truncated;
        outcome.final_info = std::move(step.info);
        break;
      }
    }
    result.episodes.push_back(std::move(outcome));
  }
  return result;
}

std::vector<Action> recorded_actions(const tendril::Policy& policy, Env& env, bool deterministic,
                                     uint64_t seed) {
  struct Recorder : envs::RunObserver {
    std::vector<Action> actions;
    void on_step(const envs::StepView& step) override { actions.push_back(step.action); }
  } recorder;
  envs::RunSettings settings;
  settings.episodes = 1;
  settings.seed = seed;
  settings.deterministic = deterministic;
  envs::run_policy(policy, env, settings, {&recorder});
  return std::move(recorder.actions);
}

}  // namespace tendril::rl
