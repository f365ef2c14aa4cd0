#pragma once

#include <cstdint>
#include <deque>
#include <functional>

#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/observer.hpp"

namespace tendril::rl {

// Returns and lengths of the last 100 finished episodes (SB3's ep_info_buffer), read from the
// EpisodeStatistics wrapper's info of each finished env, and the count of finished episodes.
class EpisodeTracker {
 public:
  void record(const envs::VecStep& step);

  int64_t episodes() const { return episodes_; }
  double mean_return() const;  // 0 when none finished yet
  double mean_length() const;
  // Oldest first.
  const std::deque<double>& recent_returns() const { return returns_; }
  // Fills the episode fields of `progress`.
  void report(Progress& progress) const;

  void save(ArchiveWriter& writer) const;
  // Reads the saved state; the returned action installs it (run once every read succeeded).
  std::function<void()> prepare_load(const ArchiveReader& reader);

 private:
  int64_t episodes_ = 0;
  std::deque<double> returns_, lengths_;
};

}  // namespace tendril::rl
