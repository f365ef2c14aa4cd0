#include "tendril/nn/inference_policy.hpp"

#include <cmath>

namespace tendril::nn {

namespace {
constexpr double kHalfLogTwoPi = 0.91893853320467274178;  // ½ log 2π
}

InferencePolicy::InferencePolicy(const ActorCriticSpec& spec)
    : spec_(spec),
      policy_trunk_(spec.observation_size, spec.policy_layers, spec.activation),
      value_trunk_(spec.observation_size,
                   spec.shared_trunk ? std::vector<int64_t>{} : spec.value_layers,
                   spec.activation) {
  const int64_t value_latent =
      spec.shared_trunk ? policy_trunk_.output_size() : value_trunk_.output_size();
  policy_head_ = {Eigen::MatrixXf::Zero(spec.action_size, policy_trunk_.output_size()),
                  Eigen::VectorXf::Zero(spec.action_size)};
  value_head_ = {Eigen::MatrixXf::Zero(1, value_latent), Eigen::VectorXf::Zero(1)};
  if (!spec.discrete) log_std_ = Eigen::VectorXf::Constant(spec.action_size, spec.log_std_init);
}

void InferencePolicy::act(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                          Rng& rng, Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs) {
  const auto batch = observations.cols();
  apply_dense(policy_head_, policy_trunk_.forward(observations), head_output_);
  actions.resize(action_dims(), batch);
  log_probs.resize(batch);
  if (spec_.discrete) {
    // Categorical over the logits: sample by inverting the cumulative distribution.
    for (Eigen::Index j = 0; j < batch; ++j) {
      const auto logits = head_output_.col(j);
      const float max_logit = logits.maxCoeff();
      const double normaliser = (logits.array() - max_logit).exp().cast<double>().sum();
      Eigen::Index choice = 0;
      if (deterministic) {
        logits.maxCoeff(&choice);
      } else {
        const double u = rng.uniform() * normaliser;
        double cumulative = 0.0;
        choice = logits.size() - 1;
        for (Eigen::Index k = 0; k < logits.size(); ++k) {
          cumulative += std::exp(static_cast<double>(logits[k] - max_logit));
          if (u < cumulative) {
            choice = k;
            break;
          }
        }
      }
      actions(0, j) = static_cast<float>(choice);
      log_probs[j] = static_cast<float>(logits[choice] - max_logit - std::log(normaliser));
    }
    return;
  }
  // Diagonal Gaussian: a = μ + σ ε, log π(a|s) = −½ Σ ε² − Σ log σ − (d/2) log 2π.
  const double log_std_sum = log_std_.cast<double>().sum();
  const double constant = -log_std_sum - static_cast<double>(spec_.action_size) * kHalfLogTwoPi;
  for (Eigen::Index j = 0; j < batch; ++j) {
    double squared_norm = 0.0;
    for (Eigen::Index i = 0; i < spec_.action_size; ++i) {
      const double epsilon = deterministic ? 0.0 : rng.normal();
      actions(i, j) = static_cast<float>(head_output_(i, j) + std::exp(log_std_[i]) * epsilon);
      squared_norm += epsilon * epsilon;
    }
    log_probs[j] = static_cast<float>(-0.5 * squared_norm + constant);
  }
}

void InferencePolicy::value(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                            Eigen::VectorXf& values) {
  const auto latent =
      spec_.shared_trunk ? policy_trunk_.forward(observations) : value_trunk_.forward(observations);
  apply_dense(value_head_, latent, value_output_);
  values = value_output_.row(0).transpose();
}

}  // namespace tendril::nn
