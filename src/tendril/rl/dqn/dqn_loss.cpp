#include "tendril/rl/dqn/dqn_loss.hpp"

#include <algorithm>
#include <cmath>

namespace tendril::rl {

double dqn_loss(const nn::DenseMlp& q_network, const Eigen::Ref<const Eigen::VectorXf>& parameters,
                const Eigen::Ref<const Eigen::VectorXf>& target_parameters,
                const ReplayBuffer::Batch& batch, double gamma, bool double_q, double q_bound,
                DqnLossWorkspace& workspace, Eigen::Ref<Eigen::VectorXf> gradient) {
  const Eigen::Index batch_size = batch.rewards.size();
  auto& [tape, next_tape, next_values, targets, output_gradient, scratch] = workspace;
  // Q = scale·z; the network's own tanh (when bounded) is inside z.
  const auto scale = static_cast<float>(q_bound > 0.0 ? q_bound : 1.0);

  q_network.forward(target_parameters, batch.next_observations, next_tape);
  next_values.resize(batch_size);
  if (double_q) {
    q_network.forward(parameters, batch.next_observations, tape);
    for (Eigen::Index i = 0; i < batch_size; ++i) {
      Eigen::Index best;
      tape.output().col(i).maxCoeff(&best);
      next_values[i] = scale * next_tape.output()(best, i);
    }
  } else {
    next_values = scale * next_tape.output().colwise().maxCoeff().transpose();
  }
  const auto discount = static_cast<float>(gamma);
  targets =
      (batch.rewards.array() + discount * (1.0f - batch.terminated.array()) * next_values.array())
          .matrix();

  q_network.forward(parameters, batch.observations, tape);
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  output_gradient.setZero(q_network.output_size(), batch_size);
  double loss_sum = 0.0;
  for (Eigen::Index i = 0; i < batch_size; ++i) {
    const auto action = static_cast<Eigen::Index>(batch.actions(0, i));
    const float error = scale * tape.output()(action, i) - targets[i];
    const float magnitude = std::abs(error);
    loss_sum += magnitude < 1.0f ? 0.5 * error * error : magnitude - 0.5;
    output_gradient(action, i) = std::clamp(error, -1.0f, 1.0f) * scale * inverse_batch;
  }
  q_network.backward(parameters, tape, output_gradient, gradient, nullptr, scratch);
  return loss_sum / static_cast<double>(batch_size);
}

}  // namespace tendril::rl
