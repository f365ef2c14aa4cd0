#pragma once

namespace tendril::envs::beam {

// Seed 003's rewards (Sec. IV–VI), one per step:
//   R = w_d r_d + w_v r_v + w_E r_E,
//   r_d = ‖tip − target‖ (m), r_v = ‖v_tip − v_target‖ (m/s), r_E = |Σ τ_i θ_i|.
// Model 1/2: w_d = −20; Model 3 cases 1–3: (w_d, w_v) = (−20, −10), (−40, −10), (−400, −200);
// the energy task (−40, −10, −1). The seed's tables are per-step means of exactly this sum,
// e.g. −40 · 0.053 − 10 · 0.127 − 1 · 1.02 = −4.41.
struct FollowWeights {
  double distance = -20.0;
  double velocity = 0.0;
  double energy = 0.0;
};

inline double follow_reward(const FollowWeights& w, double distance, double velocity_error,
                            double energy) {
  return w.distance * distance + w.velocity * velocity_error + w.energy * energy;
}

}  // namespace tendril::envs::beam
