#pragma once

#include <vector>

#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/envs/wrappers/episode_recorder.hpp"

namespace tendril::envs {

// Records every episode of a run into its own episode file (docs/episode_format.md): the scene
// of every step, the actions, rewards and info — for `tendril serve`'s 3D replay and
// `tendril plot episode`.
class EpisodeFiles : public RunObserver {
 public:
  explicit EpisodeFiles(RecordingOptions options) : tap_(std::move(options)) {}

  void on_episode_start(int64_t, uint64_t seed, const Observation&, const Env& env) override {
    tap_.started(env, seed);
  }
  void on_step(const StepView& step) override { tap_.stepped(step.env, step.action, step.result); }

  // Finished recordings, oldest first.
  const std::vector<RecordedEpisode>& episodes() const { return tap_.episodes(); }

 private:
  EpisodeTap tap_;
};

}  // namespace tendril::envs
