#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Reports each finished episode (Stable-Baselines3's Monitor, Gymnasium's RecordEpisodeStatistics):
// on the step that terminates or truncates an episode, the info gains
//   "episode_return" — the undiscounted sum of the episode's rewards,
//   "episode_length" — its number of steps,
// next to whatever the inner environment reported; its "is_success", when it sets one, passes
// through untouched. Wrap it inside reward normalization so that returns are the raw ones.
class EpisodeStatistics : public Wrapper {
 public:
  static constexpr const char* kReturnKey = "episode_return";
  static constexpr const char* kLengthKey = "episode_length";

  explicit EpisodeStatistics(std::unique_ptr<Env> inner) : Wrapper(std::move(inner)) {}

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // The running totals of the episode in progress.
  double episode_return() const { return episode_return_; }
  int64_t episode_length() const { return episode_length_; }

 private:
  double episode_return_ = 0.0;
  int64_t episode_length_ = 0;
};

}  // namespace tendril::envs
