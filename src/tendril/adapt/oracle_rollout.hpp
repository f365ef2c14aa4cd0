#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "tendril/adapt/adaptation_log.hpp"
#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::adapt {

// One closed-loop episode of the trained policy π_θ (the oracle of BOAC, seed 002 §IV-B).
struct OracleEpisode {
  Eigen::MatrixXd states;             // x_0 … x_T, one row each
  Eigen::MatrixXd commands;           // τ_0 … τ_{T−1}: the command held from t to t + 1
  std::vector<ReachStatus> statuses;  // of each step
};

// Runs π_θ deterministically on `robot` from a reset (seeded when `seed` is given) until the
// goal, a collision or `max_steps` steps.
OracleEpisode run_oracle(ReachingRobot& robot, const rl::Policy& policy, int max_steps,
                         std::optional<uint64_t> seed);

// Replays `commands` (one row per step, as OracleEpisode::commands) open loop on `robot` from a
// reset (seeded when `seed` is given), stopping early at the goal or a collision.
OracleEpisode replay_commands(ReachingRobot& robot, const Eigen::MatrixXd& commands,
                              std::optional<uint64_t> seed);

// R(n) of an episode with the goal's accuracy reduced to `radius` (seed 002 §IV-B: "each
// state-action pair has an associated reward … calculated … with reduced desired accuracy"):
// eq. (2) summed over the steps, −2 per step, −100 outside the boundary, −5 (20 − O) for
// 10 < O ≤ 20, −10000 for a collision, −G for G > radius.
double reduced_accuracy_return(const std::vector<ReachStatus>& statuses, double radius);

// The episode as logged steps of trial `trial`, appended to `steps`.
void log_oracle_episode(const OracleEpisode& episode, int trial,
                        std::vector<AdaptationStep>& steps);

}  // namespace tendril::adapt
