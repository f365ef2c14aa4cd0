#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs {

Observation EpisodeStatistics::reset(std::optional<uint64_t> seed) {
  episode_return_ = 0.0;
  episode_length_ = 0;
  return inner_->reset(seed);
}

Step EpisodeStatistics::step(const Action& action) {
  Step result = inner_->step(action);
  episode_return_ += result.reward;
  ++episode_length_;
  if (result.terminated || result.truncated) {
    result.info.set(kReturnKey, episode_return_);
    result.info.set(kLengthKey, static_cast<double>(episode_length_));
    // Totals restart here as well as on reset, so an env stepped on past the end (or a vector
    // env's auto-reset) never mixes two episodes.
    episode_return_ = 0.0;
    episode_length_ = 0;
  }
  return result;
}

}  // namespace tendril::envs
