#include "tendril/envs/runner/tracking_record.hpp"

#include <limits>
#include <string>

#include "tendril/control/reference_patterns.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {

void TrackingRecord::on_episode_start(int64_t /*episode*/, uint64_t /*seed*/,
                                      const Observation& reading, const Env& /*env*/) {
  times_.clear();
  angles_.clear();
  goals_.clear();
  throttles_.clear();
  first_on_path_ = -1;
  finished_ = over_ = policy_.progress(reading).finished;
}

void TrackingRecord::on_step(const StepView& step) {
  require(!step.result.terminated, "the limb's state became non-finite", "tracking");
  const control::TrackingPolicy::Decision& decision = policy_.last_decision();
  if (first_on_path_ < 0 && decision.on_path) {
    first_on_path_ = static_cast<Eigen::Index>(times_.size());
  }
  const control::TrackingPolicy::Progress after = policy_.progress(step.result.observation);
  times_.push_back(after.state.time_s);
  angles_.push_back(after.state.angles);
  goals_.push_back(decision.goal);
  throttles_.push_back(decision.throttles);
  finished_ = after.finished;
  over_ = finished_ || step.result.truncated;
}

TrackingRun TrackingRecord::run() const {
  TrackingRun run;
  const auto n = static_cast<Eigen::Index>(times_.size());
  run.times.resize(n);
  run.angles.resize(2, n);
  run.goals.resize(2, n);
  run.throttles.resize(2, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    run.times[k] = times_[k];
    run.angles.col(k) = angles_[k];
    run.goals.col(k) = goals_[k];
    run.throttles.col(k) = throttles_[k];
  }
  run.finished = finished_;
  run.first_on_path = first_on_path_ < 0 ? n : first_on_path_;
  run.rmse_deg = run.first_on_path < n
                     ? control::tracking_rmse(run.angles.rightCols(n - run.first_on_path),
                                              policy_.follower().points())
                     : std::numeric_limits<double>::quiet_NaN();
  return run;
}

TrackingRun track_path(const control::TrackingPolicy& policy, Env& limb, int64_t max_steps,
                       uint64_t seed, const std::vector<RunObserver*>& observers) {
  require(max_steps >= 1, "max_steps must be >= 1, got " + std::to_string(max_steps), "track_path");
  TrackingRecord record(policy);
  std::vector<RunObserver*> all{&record};
  all.insert(all.end(), observers.begin(), observers.end());
  RunSettings settings;
  settings.steps = max_steps;
  settings.seed = seed;
  settings.stop_requested = [&record] { return record.over(); };
  run_policy(policy, limb, settings, all);
  return record.run();
}

}  // namespace tendril::envs
