#pragma once

#include <Eigen/Core>

namespace tendril::nn {

// Scales `gradient` so that its L2 norm is at most `max_norm`, with the coefficient of
// torch.nn.utils.clip_grad_norm_ (max_norm / (norm + 1e-6), applied only when below 1).
// Returns the norm before clipping.
double clip_grad_norm(Eigen::Ref<Eigen::VectorXf> gradient, double max_norm);

// target ← (1 − τ) target + τ online (Polyak averaging of target networks, Lillicrap et al. 2016).
void polyak_update(Eigen::Ref<Eigen::VectorXf> target,
                   const Eigen::Ref<const Eigen::VectorXf>& online, double tau);

}  // namespace tendril::nn
