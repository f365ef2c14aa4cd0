#pragma once

#include <cstdint>
#include <vector>

#include "tendril/adapt/adaptation_log.hpp"
#include "tendril/adapt/bayesian_optimizer.hpp"
#include "tendril/adapt/coach.hpp"
#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/adapt/student_policy.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::adapt {

// The student's GP: squared exponential, a window of the latest 600 transitions, hyper-parameters
// by marginal likelihood from the previous ones plus one random restart.
GpOptions default_student_options();
// The offset's optimiser: expected improvement after 3 random trials (the seed spec's
// suggestion), the surrogate's defaults otherwise.
BayesOptOptions default_offset_optimizer_options();

struct BoacOptions {
  // d_πθ: π_θ on the robot, `oracle_trials` episodes of at most `oracle_steps`; the
  // `best_trials` (N = 7, §V-C1) with the highest reduced-accuracy return seed the student.
  // Closed loop (the policy fed the robot's states), or open loop: the commands of π_θ's
  // episodes in the model (the coach's, in turn) replayed on the robot — for a robot on which
  // the closed-loop policy collides before it gets near the goal.
  bool oracle_open_loop = false;
  int oracle_trials = 10;
  int best_trials = 7;
  int oracle_steps = 150;
  // D_d: deterministic π_θ episodes in the learned model from `coach_episodes` starts (the
  // model's rest jittered: "by changing the initial conditions of the dynamics model").
  int coach_episodes = 20;
  // Coaching profiles, mm: the coach's path ends within each radius of the goal in turn.
  std::vector<double> profiles{15.0, 10.0, 5.0};
  // L_f: a coaching trial ends within this of the coach path's end, without a collision
  // (the paper: "surrogate loss below 5 mm").
  double local_flag = 5.0;
  int batch = 5;       // n_B: transitions per retrain
  int hold_steps = 5;  // the path's last target held this long after it (the fill lag)
  int max_trials_per_profile = 8;
  int max_trials = 20;  // coaching trials in all
  // Bayesian optimisation (not specified by the paper; a choice): per profile, a 3-D offset of
  // the task point's targets in [−offset_bound, offset_bound]³ (state units), minimising the
  // trial's final distance from the coach path's end plus `collision_penalty` for a collision.
  double offset_bound = 10.0;
  double collision_penalty = 100.0;
  BayesOptOptions bayes_opt = default_offset_optimizer_options();  // bounds from offset_bound
  CoachOptions coach;
  GpOptions student = default_student_options();
  HyperparameterSharing sharing = HyperparameterSharing::shared;
};

// BOAC, Bayesian-optimisation-assisted coaching (seed 002 §IV-B, Alg. 1), on a robot: the
// oracle π_θ's best episodes on the robot train the GP student π_0 (lines 1–3); for each
// coaching profile (line 5) the coach's k-means path over π_θ's deterministic episodes in the
// learned model (`model`, a ReachingRobot over it) sets the targets x^d (moved onto each trial's
// start, the shift fading to nothing at the path's end); coaching trials
// (lines 6–7) run the student on the robot toward them, x_{t+1} ← robot(π_i(x_t, x^d)), adding
// each transition reformed as in (3) and retraining every n_B steps (lines 8–12), with Bayesian
// optimisation proposing each trial's target offset; L_f moves to the next profile, and G_f (a
// trial ending within the robot's success distance of the goal, in any profile) ends the run. The
// robot's first oracle trial starts from a reset seeded with `seed`, the model's first coach
// episode too; later ones continue the streams. Logged trials are numbered from 1: the oracle's
// first, then the coaching trials (trials_to_goal counts coaching trials only).
AdaptationResult run_boac(ReachingRobot& robot, ReachingRobot& model, const rl::Policy& oracle,
                          const BoacOptions& options, uint64_t seed);

}  // namespace tendril::adapt
