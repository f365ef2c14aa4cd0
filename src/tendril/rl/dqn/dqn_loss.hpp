#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace tendril::rl {

// Buffers reused between calls of dqn_loss so that an update allocates nothing.
struct DqnLossWorkspace {
  nn::DenseMlp::Tape tape, next_tape;
  Eigen::VectorXf next_values, targets;
  Eigen::MatrixXf output_gradient;
  std::vector<Eigen::MatrixXf> scratch;
};

// DQN's loss on one batch (Mnih et al. 2015, eq. 2, with the Huber loss of SB3's DQN.train):
//   y_i = r_i + γ (1 − d_i) Q̄(s'_i, a'_i),   L = mean_i huber(Q(s_i, a_i) − y_i),
// with a'_i = argmax_a Q̄(s'_i, a), or argmax_a Q(s'_i, a) for double DQN (van Hasselt et al.
// 2016, eq. 4); Q has `parameters`, Q̄ `target_parameters`, and y is a constant. Returns L and
// adds ∂L/∂parameters to `gradient`. Huber is smooth L1 with δ = 1, whose derivative is the
// error clamped to [−1, 1] (autograd's, ties included).
//
// With a positive `q_bound` B, Q = B·tanh(z) for the network's output z (its output layer is
// tanh, QGreedyPolicy's bounded head); with 0, Q = z.
double dqn_loss(const nn::DenseMlp& q_network, const Eigen::Ref<const Eigen::VectorXf>& parameters,
                const Eigen::Ref<const Eigen::VectorXf>& target_parameters,
                const ReplayBuffer::Batch& batch, double gamma, bool double_q, double q_bound,
                DqnLossWorkspace& workspace, Eigen::Ref<Eigen::VectorXf> gradient);

}  // namespace tendril::rl
