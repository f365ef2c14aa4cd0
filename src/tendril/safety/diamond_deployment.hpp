#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"

namespace tendril::safety {

class SafetyCritic;

// Seed 001's limb experiment (thesis §6.5, Figs. 6.6–6.7): a scripted nominal sequence that
// traces a diamond — u1 3 s, u4 3 s, u3 6 s, u2 12 s, u1 6 s, u3 3 s (the thesis' order; the
// moves of SmaLimb/LearnedSafety-v0 at full throttle) — drives the limb (SmaLimb/Robot-v0, the
// twin, in place of the hardware), filtered by a safety critic learned in a model of the limb
// (a co-training run on SmaLimb/LearnedSafety-v0): where Q_s(x, u_nominal) ≤ ε₂ the critic's
// greedy move replaces it (eq. 6.5). x = [θx, θy, θ̇x, θ̇y, t/T] with θ̇ the finite difference of
// the last two readings (as the thesis' hardware node) and t the steps since the start.
struct DiamondTrial {
  double epsilon = 0.0;
  int trial = 0;
  // Seconds from the start to the first reading with ‖θ‖ ≥ R; NaN when the sequence ends
  // without one.
  double time_to_violation_s = 0.0;
  double intervention_rate = 0.0;
  // One row per reading: time_s, theta_x, theta_y, value (Q_s of the nominal move),
  // intervened (0/1), u_x, u_y.
  Eigen::MatrixXd trajectory;
};

struct DiamondOptions {
  std::vector<double> epsilons = {0.0, 30.0, 60.0, 90.0};  // the spec's suggested sweep
  int trials = 5;                                          // per ε₂ (Fig. 6.7)
  Config limb_params;                                      // SmaLimb/Robot-v0's params
  uint64_t seed = 0;  // trial k of every ε₂ resets the twin with seed + k
};

// Runs every trial; the critic is the run's safety.critic, the safe radius and horizon the
// run's environment's.
std::vector<DiamondTrial> run_diamond(const std::filesystem::path& critic_run,
                                      const DiamondOptions& options);

// One trial: `limb` (SmaLimb/Robot-v0: readings [θx, θy, t_s]) reset with `seed` runs the diamond
// through the filter of `critic` at ε₂ = `epsilon`, with the safe radius and horizon of `task`,
// through the policy runner (the filtered sequence is a policy, the trace an observer).
DiamondTrial run_diamond_trial(Env& limb, const SafetyCritic& critic,
                               const envs::sma_limb::LearnedSafetyEnv::Params& task, double epsilon,
                               uint64_t seed);

// The diamond's move (0–3, u1–u4) at `seconds` after the start, or −1 once it is over (33 s).
int diamond_move(double seconds);

}  // namespace tendril::safety
