#pragma once

#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/data_table.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/progress_clock.hpp"
#include "tendril/envs/sma_limb/collect.hpp"
#include "tendril/envs/sma_limb/visit_grid.hpp"

// What the tasks of `tendril data` share.
namespace tendril::apps::collect {

// Robot time against the wall clock and the process's CPU time ("real time on one core").
class Stopwatch {
 public:
  Stopwatch();
  void report(double robot_s) const;

 private:
  std::chrono::steady_clock::time_point wall_;
  std::clock_t cpu_;
};

// A progress line on standard error for a collection of `robot_s` seconds of robot time: the
// robot time reached, the wall time and an ETA, at most once a second; `finish` ends the line.
class RobotTimeProgress {
 public:
  explicit RobotTimeProgress(double robot_s) : robot_s_(robot_s) {}
  void operator()(double robot_time_s);
  void finish() const;

 private:
  double robot_s_;
  ProgressClock clock_;
  double last_print_s_ = -1.0;
};

// "<file>: <path>.<key>" for error messages.
std::string where(const Config& config, const std::string& key);
// The path under `key`, which must not exist yet; its directory is created.
std::filesystem::path new_output(const Config& config, const std::string& key);
// SmaLimb/Robot-v0 with the config's `env` parameters.
std::unique_ptr<Env> limb_env(const Config& config);
std::string number(double value);

// A collection's log as a limb data set (time stamps in whole ms, angles in 0.01°).
data::Table log_table(const envs::sma_limb::LimbLog& log);
// Visits of the readings before `until_s`.
envs::sma_limb::VisitGrid coverage(const envs::sma_limb::LimbLog& log, double until_s);
// duration_s, hold_readings, cutoff_cooldown_s of the config.
envs::sma_limb::CollectSettings collect_settings(const Config& config);
// "explore" (with the config's `rule`) or "babble".
std::unique_ptr<envs::sma_limb::ThrottleSource> throttle_source(const std::string& task,
                                                                const Config& config);

// task: replay — the same open-loop throttles after different cool-downs (Fig. 1.1c).
int replay(const Config& config);
// task: open_loop — the limb driven by the open-loop test inputs (Fig. 4.4's ground truth).
int open_loop(const Config& config);
// task: coverage — exploration against babbling over several seeds (Fig. 4.2).
int compare_coverage(const Config& config);

}  // namespace tendril::apps::collect
