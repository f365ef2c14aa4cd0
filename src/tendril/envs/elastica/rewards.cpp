#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {

double reach_reward(double distance) {
  double reward = -distance * distance;
  if (distance <= 2.0 * kBonusRange) reward += 0.5;
  if (distance <= kBonusRange) reward += 1.5;
  return reward;
}

double orientation_penalty(const Eigen::Quaterniond& tip, const Eigen::Quaterniond& target) {
  const double alignment = tip.coeffs().dot(target.coeffs());
  return 1.0 - alignment * alignment;
}

double oriented_reach_reward(double distance, double p) {
  double reward = -distance * distance - 0.5 * p * p;
  if (distance <= kBonusRange) {
    if (p <= 0.05) {
      reward += 6.0 - 2.0 * p;
    } else if (p <= 0.1) {
      reward += 4.5 - 2.0 * p;
    } else {
      reward += 4.0 - 2.0 * p;
    }
  } else if (distance <= 2.0 * kBonusRange) {
    reward += (p <= 0.1 ? 1.5 : 1.0) - 0.5 * p;
  }
  return reward;
}

}  // namespace tendril::envs::elastica
