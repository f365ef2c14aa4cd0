#include "tendril/rl/episode_tracker.hpp"

#include <numeric>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/wrappers/curriculum.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::rl {

namespace {

constexpr std::size_t kWindow = 100;  // SB3's ep_info_buffer

double mean(const std::deque<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

}  // namespace

void EpisodeTracker::record(const envs::VecStep& step) {
  for (std::size_t i = 0; i < step.infos.size(); ++i) {
    if (!step.done(static_cast<int>(i))) continue;
    const auto episode_return = step.infos[i].get(envs::EpisodeStatistics::kReturnKey);
    const auto episode_length = step.infos[i].get(envs::EpisodeStatistics::kLengthKey);
    if (const auto success = step.infos[i].get(info_keys::kIsSuccess)) {
      successes_.push_back(*success > 0.5 ? 1.0 : 0.0);
      if (successes_.size() > kWindow) successes_.pop_front();
    }
    if (const auto level = step.infos[i].get(envs::Curriculum::kLevelKey)) {
      levels_.push_back(*level);
      if (levels_.size() > kWindow) levels_.pop_front();
    }
    if (!episode_return || !episode_length) continue;
    returns_.push_back(*episode_return);
    lengths_.push_back(*episode_length);
    if (returns_.size() > kWindow) {
      returns_.pop_front();
      lengths_.pop_front();
    }
    ++episodes_;
  }
}

double EpisodeTracker::mean_return() const { return mean(returns_); }
double EpisodeTracker::mean_length() const { return mean(lengths_); }

std::optional<double> EpisodeTracker::success_rate() const {
  if (successes_.empty()) return std::nullopt;
  return mean(successes_);
}

std::optional<double> EpisodeTracker::curriculum_level() const {
  if (levels_.empty()) return std::nullopt;
  return mean(levels_);
}

void EpisodeTracker::report(Progress& progress) const {
  progress.episodes = episodes_;
  progress.episode_return_mean = mean_return();
  progress.episode_length_mean = mean_length();
  progress.success_rate = success_rate();
  progress.curriculum_level = curriculum_level();
}

void EpisodeTracker::save(ArchiveWriter& writer) const {
  writer.put("episodes", episodes_);
  writer.put_doubles("recent_returns", std::vector<double>(returns_.begin(), returns_.end()));
  writer.put_doubles("recent_lengths", std::vector<double>(lengths_.begin(), lengths_.end()));
  writer.put_doubles("recent_successes", std::vector<double>(successes_.begin(), successes_.end()));
  writer.put_doubles("recent_levels", std::vector<double>(levels_.begin(), levels_.end()));
}

std::function<void()> EpisodeTracker::prepare_load(const ArchiveReader& reader) {
  const int64_t episodes = reader.get_int("episodes");
  const std::vector<double> returns = reader.get_doubles("recent_returns");
  const std::vector<double> lengths = reader.get_doubles("recent_lengths");
  // Checkpoints written before success rates were tracked have none.
  const std::vector<double> successes = reader.contains("recent_successes")
                                            ? reader.get_doubles("recent_successes")
                                            : std::vector<double>{};
  // ... and those written before curriculum levels were, none of these.
  const std::vector<double> levels = reader.contains("recent_levels")
                                         ? reader.get_doubles("recent_levels")
                                         : std::vector<double>{};
  require(returns.size() == lengths.size() && returns.size() <= kWindow &&
              successes.size() <= kWindow && levels.size() <= kWindow,
          "episode records are inconsistent", reader.name());
  return [this, episodes, returns, lengths, successes, levels] {
    episodes_ = episodes;
    returns_.assign(returns.begin(), returns.end());
    lengths_.assign(lengths.begin(), lengths.end());
    successes_.assign(successes.begin(), successes.end());
    levels_.assign(levels.begin(), levels.end());
  };
}

}  // namespace tendril::rl
