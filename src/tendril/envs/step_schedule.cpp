#include "tendril/envs/step_schedule.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

std::string key_of(const Config& params, const std::string& key) {
  return params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key;
}

}  // namespace

StepSchedule StepSchedule::constant(double value) {
  require(std::isfinite(value), "a schedule's value must be finite", "StepSchedule");
  return StepSchedule(value, value, 0);
}

StepSchedule StepSchedule::linear(double start, double end, int64_t steps) {
  require(std::isfinite(start) && std::isfinite(end), "start and end must be finite",
          "StepSchedule");
  require(steps >= 1, "steps must be at least 1, got " + std::to_string(steps), "StepSchedule");
  return StepSchedule(start, end, steps);
}

StepSchedule StepSchedule::from_config(const Config& params, const std::string& key,
                                       double fallback) {
  const std::string schedule_key = key + "_schedule";
  if (!params.has(schedule_key)) {
    const double value = params.get_or<double>(key, fallback);
    require(std::isfinite(value), "must be finite", key_of(params, key));
    return constant(value);
  }
  require(!params.has(key), "give either " + key + " or " + schedule_key + ", not both",
          key_of(params, key));
  const Config schedule = params.child(schedule_key);
  const double start = schedule.get<double>("start");
  const double end = schedule.get<double>("end");
  const int64_t steps = schedule.get<int64_t>("steps");
  schedule.reject_unknown();
  require(std::isfinite(start) && std::isfinite(end), "start and end must be finite",
          key_of(params, schedule_key));
  require(steps >= 1, "steps must be at least 1, got " + std::to_string(steps),
          key_of(params, schedule_key + ".steps"));
  return linear(start, end, steps);
}

double StepSchedule::value(int64_t step) const {
  if (steps_ == 0 || step >= steps_) return end_;
  if (step <= 0) return start_;
  // λ(t) = start + (t / T)·(end − start)  (seed 004, Sec. 3.1.3).
  return start_ + (static_cast<double>(step) / static_cast<double>(steps_)) * (end_ - start_);
}

}  // namespace tendril::envs
