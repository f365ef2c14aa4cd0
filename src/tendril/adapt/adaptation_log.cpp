#include "tendril/adapt/adaptation_log.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// Enough digits to read a double back exactly where it matters (mm to 1 µm, ms to 1 µs).
std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

void put_vector(std::ostringstream& out, const Eigen::VectorXd& values, int size) {
  for (int i = 0; i < size; ++i) {
    out << ',' << (i < values.size() ? number(values[i]) : std::string("nan"));
  }
}

}  // namespace

AdaptationTrial summarize_trial(int trial, std::string phase,
                                const std::vector<AdaptationStep>& steps, std::size_t first_step) {
  AdaptationTrial summary;
  summary.trial = trial;
  summary.phase = std::move(phase);
  require(first_step < steps.size(), "a trial without steps", "adapt::summarize_trial");
  summary.steps = static_cast<int>(steps.size() - first_step);
  summary.min_goal_distance = steps[first_step].status.goal_distance;
  summary.min_obstacle_distance = steps[first_step].status.obstacle_distance;
  std::vector<double> update_ms;
  for (std::size_t i = first_step; i < steps.size(); ++i) {
    summary.min_goal_distance = std::min(summary.min_goal_distance, steps[i].status.goal_distance);
    summary.min_obstacle_distance =
        std::min(summary.min_obstacle_distance, steps[i].status.obstacle_distance);
    update_ms.push_back(1e3 * steps[i].update_seconds);
  }
  const ReachStatus& last = steps.back().status;
  summary.success = last.success;
  summary.collision = last.collision;
  summary.final_goal_distance = last.goal_distance;
  std::sort(update_ms.begin(), update_ms.end());
  summary.max_update_ms = update_ms.back();
  summary.median_update_ms = update_ms[update_ms.size() / 2];
  return summary;
}

void write_adaptation_logs(const std::filesystem::path& directory, const AdaptationResult& result,
                           const std::vector<std::string>& state_names) {
  const int size = static_cast<int>(state_names.size());
  std::ostringstream steps;
  steps << "trial,step";
  for (const char* group : {"", "command_", "reference_"}) {
    for (const std::string& name : state_names) {
      steps << ',' << group << name;
    }
  }
  steps << ",goal_distance_mm,obstacle_distance_mm,reward,success,collision,outside,rate_limited,"
           "update_ms\n";
  for (const AdaptationStep& step : result.steps) {
    steps << step.trial << ',' << step.step;
    put_vector(steps, step.state, size);
    put_vector(steps, step.command, size);
    put_vector(steps, step.reference, size);
    const ReachStatus& s = step.status;
    steps << ',' << number(s.goal_distance) << ',' << number(s.obstacle_distance) << ','
          << number(s.reward) << ',' << s.success << ',' << s.collision << ',' << s.outside << ','
          << s.rate_limited << ',' << number(1e3 * step.update_seconds) << '\n';
  }
  std::ostringstream trials;
  trials << "trial,phase,steps,success,collision,final_goal_distance_mm,min_goal_distance_mm,"
            "min_obstacle_distance_mm,tracking_rms_mm,coach_end_distance_mm,max_update_ms,"
            "median_update_ms,search_s\n";
  for (const AdaptationTrial& t : result.trials) {
    trials << t.trial << ',' << t.phase << ',' << t.steps << ',' << t.success << ',' << t.collision
           << ',' << number(t.final_goal_distance) << ',' << number(t.min_goal_distance) << ','
           << number(t.min_obstacle_distance) << ',' << number(t.tracking_rms) << ','
           << number(t.coach_end_distance) << ',' << number(t.max_update_ms) << ','
           << number(t.median_update_ms) << ',' << number(t.search_seconds) << '\n';
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw Error("cannot create the directory: " + error.message(), directory.string());
  write_file_atomically(directory / "steps.csv", steps.str(), "adaptation log");
  write_file_atomically(directory / "trials.csv", trials.str(), "adaptation log");
}

}  // namespace tendril::adapt
