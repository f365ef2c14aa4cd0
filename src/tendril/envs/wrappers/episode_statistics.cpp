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

void EpisodeStatistics::save_state(SnapshotWriter& out) const {
  out.section("EpisodeStatistics");
  out.put(episode_return_);
  out.put(episode_length_);
  inner_->save_state(out);
}

void EpisodeStatistics::load_state(SnapshotReader& in) {
  in.section("EpisodeStatistics");
  const double episode_return = in.get_double();
  const int64_t episode_length = in.get_int64();
  inner_->load_state(in);
  episode_return_ = episode_return;
  episode_length_ = episode_length;
}

}  // namespace tendril::envs
