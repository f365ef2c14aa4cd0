#pragma once

// LibTorch versions of tendril's hand-differentiated networks, reading the same flat parameter
// vector through views of one leaf tensor: autograd on that leaf is the oracle for every hand
// derivation (gradients, Jacobian-vector and Fisher-vector products).
#include <torch/torch.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/dense_mlp.hpp"

namespace tendril::testing {

// A copy of a flat parameter vector as a 1-D leaf tensor that requires gradients.
inline torch::Tensor leaf(const Eigen::VectorXf& parameters) {
  return torch::from_blob(const_cast<float*>(parameters.data()), {parameters.size()})
      .clone()
      .requires_grad_(true);
}

// A features × batch matrix as a [batch, features] tensor (a copy).
inline torch::Tensor rows_of(const Eigen::MatrixXf& columns) {
  return torch::from_blob(const_cast<float*>(columns.data()), {columns.cols(), columns.rows()})
      .clone();
}

// A [batch, features] tensor as a features × batch matrix.
inline Eigen::MatrixXf columns_of(const torch::Tensor& rows) {
  const torch::Tensor contiguous = rows.detach().contiguous();
  return Eigen::Map<const Eigen::MatrixXf>(contiguous.data_ptr<float>(), rows.size(1),
                                           rows.size(0));
}

inline Eigen::VectorXf vector_of(const torch::Tensor& values) {
  const torch::Tensor contiguous = values.detach().contiguous().reshape({-1});
  return Eigen::Map<const Eigen::VectorXf>(contiguous.data_ptr<float>(), contiguous.numel());
}

inline torch::Tensor activate(nn::Activation activation, const torch::Tensor& x) {
  switch (activation) {
    case nn::Activation::kTanh:
      return torch::tanh(x);
    case nn::Activation::kRelu:
      return torch::relu(x);
    case nn::Activation::kSoftsign:
      return x / (1 + torch::abs(x));
  }
  return x;
}

// `mlp` with its parameters at theta[offset, offset + count), on x [batch, in].
inline torch::Tensor mlp_forward(const nn::DenseMlp& mlp, const torch::Tensor& theta,
                                 int64_t offset, torch::Tensor x) {
  const auto& sizes = mlp.sizes();
  for (std::size_t layer = 0; layer + 1 < sizes.size(); ++layer) {
    const int64_t in = sizes[layer], out = sizes[layer + 1];
    const torch::Tensor weight = theta.narrow(0, offset, out * in).reshape({out, in});
    offset += out * in;
    const torch::Tensor bias = theta.narrow(0, offset, out);
    offset += out;
    x = torch::nn::functional::linear(x, weight, bias);
    const bool last = layer + 2 == sizes.size();
    if (!last || mlp.activates_output()) {
      x = activate(mlp.hidden_activation(), x);
    } else if (mlp.tanh_output()) {
      x = torch::tanh(x);
    }
  }
  return x;
}

// An actor-critic's outputs computed by LibTorch from the layout nn::ActorCritic documents:
// [policy trunk | policy head | log σ | value trunk | value head].
struct TorchActorCritic {
  torch::Tensor head;     // μ or logits [batch, n]
  torch::Tensor log_std;  // [n] (Gaussian)
  torch::Tensor value;    // [batch]

  TorchActorCritic(const nn::ActorCriticSpec& spec, const torch::Tensor& theta,
                   const torch::Tensor& observations) {
    int64_t offset = 0;
    const auto trunk = [&](const std::vector<int64_t>& layers, const torch::Tensor& x) {
      if (layers.empty()) return x;
      std::vector<int64_t> sizes{spec.observation_size};
      sizes.insert(sizes.end(), layers.begin(), layers.end());
      const nn::DenseMlp mlp = nn::DenseMlp::trunk(sizes, spec.activation);
      const torch::Tensor y = mlp_forward(mlp, theta, offset, x);
      offset += mlp.parameter_count();
      return y;
    };
    const auto linear = [&](int64_t in, int64_t out, const torch::Tensor& x) {
      const nn::DenseMlp mlp({in, out}, spec.activation);
      const torch::Tensor y = mlp_forward(mlp, theta, offset, x);
      offset += mlp.parameter_count();
      return y;
    };
    const torch::Tensor policy_latent = trunk(spec.policy_layers, observations);
    head = linear(policy_latent.size(1), spec.action_size, policy_latent);
    if (spec.policy_output_activation) head = activate(*spec.policy_output_activation, head);
    if (!spec.discrete) {
      log_std = theta.narrow(0, offset, spec.action_size);
      offset += spec.action_size;
    }
    const torch::Tensor value_latent =
        spec.shared_trunk ? policy_latent : trunk(spec.value_layers, observations);
    value = linear(value_latent.size(1), 1, value_latent).squeeze(1);
  }

  torch::Tensor log_prob(const torch::Tensor& actions, bool discrete) const {
    if (discrete) {
      return torch::log_softmax(head, 1).gather(1, actions.to(torch::kLong)).squeeze(1);
    }
    const torch::Tensor z = (actions - head) * torch::exp(-log_std);
    return (-0.5 * z.pow(2) - log_std - 0.5 * std::log(2.0 * M_PI)).sum(1);
  }
  torch::Tensor entropy(bool discrete) const {
    if (discrete) {
      const torch::Tensor log_p = torch::log_softmax(head, 1);
      return -(log_p.exp() * log_p).sum(1);
    }
    return (log_std + 0.5 + 0.5 * std::log(2.0 * M_PI)).sum().expand({head.size(0)});
  }
  // Mean over samples of KL(old ‖ this).
  torch::Tensor mean_kl(const TorchActorCritic& old, bool discrete) const {
    if (discrete) {
      const torch::Tensor log_p = torch::log_softmax(old.head, 1);
      const torch::Tensor log_q = torch::log_softmax(head, 1);
      return (log_p.exp() * (log_p - log_q)).sum(1).mean();
    }
    const torch::Tensor variance_old = torch::exp(2.0 * old.log_std);
    const torch::Tensor variance_new = torch::exp(2.0 * log_std);
    return (log_std - old.log_std +
            (variance_old + (old.head - head).pow(2)) / (2.0 * variance_new) - 0.5)
        .sum(1)
        .mean();
  }
};

}  // namespace tendril::testing
