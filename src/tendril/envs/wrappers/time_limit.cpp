#include "tendril/envs/wrappers/time_limit.hpp"

#include <string>

namespace tendril::envs {

TimeLimit::TimeLimit(std::unique_ptr<Env> inner, int64_t max_episode_steps)
    : Wrapper(std::move(inner)), max_episode_steps_(max_episode_steps) {
  require(max_episode_steps >= 1,
          "max_episode_steps must be at least 1, got " + std::to_string(max_episode_steps),
          "envs::TimeLimit");
}

Observation TimeLimit::reset(std::optional<uint64_t> seed) {
  elapsed_steps_ = 0;
  has_reset_ = true;
  return inner_->reset(seed);
}

Step TimeLimit::step(const Action& action) {
  require(has_reset_, "step called before reset", "envs::TimeLimit");
  Step result = inner_->step(action);
  ++elapsed_steps_;
  if (elapsed_steps_ >= max_episode_steps_ && !result.terminated) result.truncated = true;
  return result;
}

void TimeLimit::save_state(SnapshotWriter& out) const {
  out.section("TimeLimit");
  out.put(elapsed_steps_);
  out.put(has_reset_);
  inner_->save_state(out);
}

void TimeLimit::load_state(SnapshotReader& in) {
  in.section("TimeLimit");
  const int64_t elapsed = in.get_int64();
  const bool has_reset = in.get_bool();
  inner_->load_state(in);
  elapsed_steps_ = elapsed;
  has_reset_ = has_reset;
}

}  // namespace tendril::envs
