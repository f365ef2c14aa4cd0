#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::envs {

// How run_policy runs a policy. Exactly one of `episodes` and `steps` is positive.
struct RunSettings {
  int64_t episodes = 0;  // whole episodes (the environment must end them, e.g. by a time limit)
  int64_t steps = 0;     // steps; the episode running when they are used up is cut short
  // Episode k resets with seed + k, so any one episode can be run again on its own
  // (`--seed S+k --episodes 1`); a stochastic policy draws from a stream of its own seeded with
  // `seed`.
  uint64_t seed = 0;
  bool deterministic = true;  // the policy's mode; false samples
  // Stop politely after the current step when it returns true (a caught Ctrl-C, or a scripted
  // experiment whose sequence is over, e.g. safety::run_diamond_trial): the episode running then
  // counts as cut short.
  std::function<bool()> stop_requested;
};

// One episode of a run: its index k (reset with seed + k), return, length and how it ended.
struct EpisodeOutcome {
  int64_t index = 0;
  uint64_t seed = 0;
  double episode_return = 0.0;  // undiscounted
  int64_t length = 0;
  bool terminated = false;
  bool truncated = false;
  bool finished = true;  // false: cut short by the step budget
  Info final_info;       // the last step's info (success, distances, …)
};

// One step of a run, as observers see it.
struct StepView {
  int64_t episode = 0;             // index k
  int64_t step = 0;                // within the episode, from 0
  const Observation& observation;  // before the step
  const Action& action;            // as the policy chose it (environment units)
  const Step& result;
  const Env& env;  // after the step (its scene, its snapshot)
};

// Sees a run as it happens: summary statistics, a transition trace, episode files, tracking
// errors are observers (envs/runner/*).
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_episode_start(int64_t /*episode*/, uint64_t /*seed*/,
                                const Observation& /*observation*/, const Env& /*env*/) {}
  virtual void on_step(const StepView& /*step*/) {}
  virtual void on_episode_end(const EpisodeOutcome& /*outcome*/) {}
};

struct RunResult {
  std::vector<EpisodeOutcome> episodes;  // in index order; a cut-short last one included
  int64_t steps = 0;
  bool stopped = false;  // by RunSettings::stop_requested

  // Over the finished episodes.
  int64_t finished_episodes() const;
  double mean_return() const;
  double std_return() const;  // population standard deviation, as SB3 reports it
  double mean_length() const;
  // The fraction of finished episodes whose last info reports is_success > 0.5; none when no
  // episode's last info has is_success.
  std::optional<double> success_rate() const;
};

// Runs `policy` on `env` as `settings` say, calling the observers at every start, step and end.
RunResult run_policy(const Policy& policy, Env& env, const RunSettings& settings,
                     const std::vector<RunObserver*>& observers = {});

// The same `settings.episodes` episodes over the N environments of a vector env stepped together
// (one batched policy call and, for a batched env, one model call per step): episode k still
// resets with seed + k (VecEnv::seed_next_reset), whichever environment runs it, so with a
// deterministic policy on independently stepped environments (ThreadedVecEnv) the outcomes equal
// the single-environment run's. Rewards are the vector env's (raw unless it normalizes them).
RunResult run_policy(const Policy& policy, VecEnv& env, const RunSettings& settings);

}  // namespace tendril::envs
