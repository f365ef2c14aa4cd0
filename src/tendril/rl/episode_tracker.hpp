#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>

#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/observer.hpp"

namespace tendril::rl {

// Returns and lengths of the last 100 finished episodes (SB3's ep_info_buffer), read from the
// EpisodeStatistics wrapper's info of each finished env, and the count of finished episodes;
// and, for environments that report "is_success" on an episode's last step, whether each of the
// last 100 such episodes succeeded (SB3's ep_success_buffer, logged as rollout/success_rate);
// and, for environments under a curriculum ("curriculum_level" in info), the level of each of the
// last 100 episodes (logged as rollout/curriculum_level, their mean).
class EpisodeTracker {
 public:
  void record(const envs::VecStep& step);

  int64_t episodes() const { return episodes_; }
  double mean_return() const;  // 0 when none finished yet
  double mean_length() const;
  // Fraction of the last 100 episodes that reported is_success = 1; unset until one reported.
  std::optional<double> success_rate() const;
  // Mean curriculum level of the last 100 episodes that reported one; unset until one did.
  std::optional<double> curriculum_level() const;
  // Oldest first.
  const std::deque<double>& recent_returns() const { return returns_; }
  // Fills the episode fields of `progress`.
  void report(Progress& progress) const;

  void save(ArchiveWriter& writer) const;
  // Reads the saved state; the returned action installs it (run once every read succeeded).
  std::function<void()> prepare_load(const ArchiveReader& reader);

 private:
  int64_t episodes_ = 0;
  std::deque<double> returns_, lengths_, successes_, levels_;
};

}  // namespace tendril::rl
