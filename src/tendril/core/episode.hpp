#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/scene.hpp"
#include "tendril/core/space.hpp"

namespace tendril {

// A recorded episode: what a viewer replays and a figure draws (docs/episode_format.md). One
// frame per environment step plus one for the state after reset; each frame holds the scene the
// environment described (Env::describe_scene), the action that led to it, its reward and info.
struct EpisodeFrame {
  int64_t step = 0;     // actions taken so far; 0 is the state after reset
  double reward = 0.0;  // of the action that led to this frame (0 at step 0)
  bool terminated = false;
  bool truncated = false;
  Action action;  // the action that led to this frame; empty at step 0
  std::vector<std::pair<std::string, double>> info;  // the step's Info entries
  Scene scene;  // lab frame, metres; scene.time in seconds since reset
};

// What the end of a finished recording states.
struct EpisodeSummary {
  int64_t steps = 0;
  double episode_return = 0.0;  // sum of the frames' rewards
  bool terminated = false;
  bool truncated = false;
};

using EpisodeMetadata = std::vector<std::pair<std::string, std::string>>;

struct Episode {
  EpisodeMetadata metadata;  // env id, run directory, policy, seed, ...
  int action_size = 0;
  std::vector<EpisodeFrame> frames;
  std::optional<EpisodeSummary> summary;  // absent when the recording did not finish

  // The value of a metadata key, or `fallback`.
  std::string meta(const std::string& key, const std::string& fallback = {}) const;
};

}  // namespace tendril
