#pragma once

#include <Eigen/Geometry>

namespace tendril::envs::elastica {

// Rewards of the Elastica control cases (seed 000, "Reward Function Definition" of each case;
// SPEC M2). d is the distance between the arm's tip and the target's centre, m.
//
// Reading of the seed: its n (“the square of the L2 norm distance … n = ‖x_n − x_t‖”) is the
// distance itself, penalized as −n²; its bonus range is d = 5 cm, the cases "d < n < 2d" and
// "n < d" meaning 5–10 cm and under 5 cm, taken with inclusive upper bounds as in SPEC M2
// (0.1 m and 0.05 m belong to the better tier). The seed's g(S) is not defined beyond the NaN
// penalty it describes next ("a penalty term of −1000 was added any time a NaN was detected");
// the environments apply that penalty on the step that ends the episode, as the whole reward.

inline constexpr double kBonusRange = 0.05;  // m, the seed's d

// Cases 1, 3, 4: −d² + 0.5 if d ≤ 0.1 m, + 1.5 more if d ≤ 0.05 m (2.0 in all).
double reach_reward(double distance);

// The seed's orientation penalty p = 1 − (q_a · q_t)² of two unit quaternions (4-D dot
// product): 0 for equal frames, whatever the sign of either quaternion; 1 for frames half a
// turn apart; 1 − cos²(φ/2) = sin²(φ/2) for a rotation by φ between them.
double orientation_penalty(const Eigen::Quaterniond& tip, const Eigen::Quaterniond& target);

// Case 2: −d² − 0.5 p² plus the seed's graded bonus
//   5 cm < d ≤ 10 cm:  1.0 − 0.5 p  (p > 0.1)     1.5 − 0.5 p  (p ≤ 0.1)
//   d ≤ 5 cm:          4.0 − 2.0 p  (p > 0.1)     4.5 − 2.0 p  (0.05 < p ≤ 0.1)
//                      6.0 − 2.0 p  (p ≤ 0.05)
// The seed writes the tiers with strict inequalities both ways, which leaves p = 0.1 and
// p = 0.05 unassigned; they are given to the better tier, like the distance bounds.
double oriented_reach_reward(double distance, double orientation_penalty);

}  // namespace tendril::envs::elastica
