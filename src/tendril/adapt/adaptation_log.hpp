#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/adapt/reaching_robot.hpp"

namespace tendril::adapt {

// One control step of an online-adaptation trial on the robot (seed 002 §V-C, V-D).
struct AdaptationStep {
  int trial = 0;            // from 1, in the order the trials ran
  int step = 0;             // from 0 within the trial
  Eigen::VectorXd state;    // x_{t+1}, measured after the step
  Eigen::VectorXd command;  // the command held from t to t + 1 (normalised)
  // What the controller steered by: GPRCA, the compensated state s_t = x_t + c_t the policy saw;
  // BOAC, the coach's target x^d the student was asked to reach.
  Eigen::VectorXd reference;
  ReachStatus status;           // of the step, on the measured state
  double update_seconds = 0.0;  // the learner's work after the step (retrain, prediction)
};

// One trial: a run of the robot from rest until the goal, a collision or the trial's length.
struct AdaptationTrial {
  int trial = 0;      // from 1
  std::string phase;  // "oracle", "coach 15 mm", …, "gprca"
  int steps = 0;
  bool success = false;    // ended within the task's success distance (the goal flag)
  bool collision = false;  // ended by a collision
  double final_goal_distance = 0.0;
  double min_goal_distance = 0.0;
  double min_obstacle_distance = 0.0;
  // BOAC: the RMS distance of the task point from the coach path's points (before the trial's
  // offset and start shift), and its final distance from the path's end.
  double tracking_rms = 0.0;
  double coach_end_distance = 0.0;
  double max_update_ms = 0.0, median_update_ms = 0.0;  // per step
  double search_seconds = 0.0;                         // hyper-parameter search after the trial
};

struct AdaptationResult {
  std::vector<AdaptationTrial> trials;
  std::vector<AdaptationStep> steps;
  bool goal_flag = false;  // G_f: a trial of the adaptation (not the oracle's) ended at the goal
  int trials_to_goal = 0;  // adaptation trials up to and including the first at the goal
};

// Fills the trial's step count, outcome, distances and update times from its steps.
AdaptationTrial summarize_trial(int trial, std::string phase,
                                const std::vector<AdaptationStep>& steps, std::size_t first_step);

// Writes `steps.csv` (one row per step: trial, step, the state, command and reference columns
// named from `state_names`, goal and obstacle distance, reward, the flags, update_ms) and
// `trials.csv` (one row per AdaptationTrial) into `directory` (created), atomically.
void write_adaptation_logs(const std::filesystem::path& directory, const AdaptationResult& result,
                           const std::vector<std::string>& state_names);

}  // namespace tendril::adapt
