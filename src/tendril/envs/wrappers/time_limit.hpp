#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Ends an episode after `max_episode_steps` steps by setting `truncated` (Gymnasium's TimeLimit).
// `truncated` is set only when the task did not also terminate on that step: a step is then
// either terminated (do not bootstrap) or truncated (bootstrap from the observation), never
// both, so a learner reading `truncated` alone bootstraps correctly. (Gymnasium would report
// both flags on such a step.)
class TimeLimit : public Wrapper {
 public:
  TimeLimit(std::unique_ptr<Env> inner, int64_t max_episode_steps);

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  // Raises Error if called before the first reset.
  Step step(const Action& action) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  int64_t max_episode_steps() const { return max_episode_steps_; }
  int64_t elapsed_steps() const { return elapsed_steps_; }

 private:
  int64_t max_episode_steps_;
  int64_t elapsed_steps_ = 0;
  bool has_reset_ = false;
};

}  // namespace tendril::envs
