#include "tendril/nn/dense_actor_critic.hpp"

#include <cmath>
#include <cstdint>

#include "tendril/core/error.hpp"

namespace tendril::nn {

namespace {

constexpr float kHalfLogTwoPi = 0.91893853320467274178f;  // ½ log 2π
constexpr const char* kWhere = "nn::DenseActorCritic";

// Where `parameter` starts in the flat buffer, checking that it is a contiguous view of it.
int64_t offset_in(const torch::Tensor& parameter, const FlatParameters& flat) {
  const auto base = reinterpret_cast<std::uintptr_t>(flat.values().data_ptr<float>());
  const auto data = reinterpret_cast<std::uintptr_t>(parameter.data_ptr<float>());
  const auto offset = static_cast<int64_t>((data - base) / sizeof(float));
  require(data >= base && parameter.is_contiguous() && offset + parameter.numel() <= flat.numel(),
          "a parameter of the actor-critic is not a view of the flat parameter buffer", kWhere);
  return offset;
}

// Where `layers` start in the flat buffer, checking that they lie one after the other, each
// as weight then bias: the layout DenseMlp reads.
int64_t offset_of_layers(const std::vector<torch::nn::Linear>& layers, const FlatParameters& flat) {
  const int64_t start = offset_in(layers.front()->weight, flat);
  int64_t next = start;
  for (const auto& layer : layers) {
    require(offset_in(layer->weight, flat) == next &&
                offset_in(layer->bias, flat) == next + layer->weight.numel(),
            "the layers of a network are not adjacent in the flat parameter buffer", kWhere);
    next += layer->weight.numel() + layer->bias.numel();
  }
  return start;
}

std::vector<int64_t> layer_sizes(const std::vector<torch::nn::Linear>& layers) {
  std::vector<int64_t> sizes{layers.front()->weight.size(1)};
  for (const auto& layer : layers) sizes.push_back(layer->weight.size(0));
  return sizes;
}

Eigen::Ref<const Eigen::VectorXf> segment(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                          int64_t offset, const DenseMlp& mlp) {
  return parameters.segment(offset, mlp.parameter_count());
}

// e^x with std::exp, element by element: these vectors are a handful of actions or choices
// long, and Eigen's vectorised exp trips a false -Wuninitialized in GCC 12's AVX-512 headers.
constexpr auto exp_of = [](float x) { return std::exp(x); };

// A 1 × batch row as the matrix DenseMlp takes, without a copy.
Eigen::Map<const Eigen::MatrixXf> as_matrix(const Eigen::Ref<const Eigen::RowVectorXf>& row) {
  return {row.data(), 1, row.size()};
}

}  // namespace

DenseActorCritic::DenseActorCritic(const ActorCriticImpl& policy, const FlatParameters& flat)
    : discrete_(policy.spec().discrete),
      shared_trunk_(policy.spec().shared_trunk),
      action_size_(policy.spec().action_size),
      parameter_count_(flat.numel()) {
  int64_t count = 0;
  for (const auto& p : policy.parameters()) count += p.numel();
  require(count == flat.numel(), "the flat buffer does not hold exactly this actor-critic", kWhere);
  const auto place_trunk = [&](const Mlp& trunk) -> std::optional<Placed> {
    if (trunk.is_empty() || trunk->layers().empty()) return std::nullopt;
    return Placed{DenseMlp::trunk(layer_sizes(trunk->layers()), trunk->activation()),
                  offset_of_layers(trunk->layers(), flat)};
  };
  const auto place_head = [&](const torch::nn::Linear& head) {
    // One linear layer: the hidden activation is never used.
    return Placed{DenseMlp(layer_sizes({head}), Activation::kTanh), offset_of_layers({head}, flat)};
  };
  policy_trunk_ = place_trunk(policy.policy_trunk());
  if (!shared_trunk_) value_trunk_ = place_trunk(policy.value_trunk());
  policy_head_ = place_head(policy.policy_head());
  value_head_ = place_head(policy.value_head());
  if (!discrete_) log_std_offset_ = offset_in(policy.log_std(), flat);
}

void DenseActorCritic::evaluate(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                const Eigen::Ref<const Eigen::MatrixXf>& actions,
                                Tape& tape) const {
  const auto latent = [&](const std::optional<Placed>& trunk,
                          Tape::Pass& pass) -> Eigen::Ref<const Eigen::MatrixXf> {
    if (!trunk) return observations;
    trunk->mlp.forward(segment(parameters, trunk->offset, trunk->mlp), observations, pass.tape);
    return pass.tape.output();
  };
  const Eigen::Ref<const Eigen::MatrixXf> policy_latent = latent(policy_trunk_, tape.policy_trunk);
  policy_head_.mlp.forward(segment(parameters, policy_head_.offset, policy_head_.mlp),
                           policy_latent, tape.policy_head.tape);
  distribution_forward(parameters, actions, tape);

  const Eigen::Ref<const Eigen::MatrixXf> value_latent =
      shared_trunk_ ? policy_latent : latent(value_trunk_, tape.value_trunk);
  value_head_.mlp.forward(segment(parameters, value_head_.offset, value_head_.mlp), value_latent,
                          tape.value_head.tape);
  tape.value = tape.value_head.tape.output().row(0);
}

void DenseActorCritic::distribution_forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                            const Eigen::Ref<const Eigen::MatrixXf>& actions,
                                            Tape& tape) const {
  const Eigen::MatrixXf& head_output = tape.policy_head.tape.output();
  const int64_t batch = head_output.cols();
  if (!discrete_) {
    // Diagonal Gaussian N(μ, diag σ²) with state-independent log σ:
    //   log π(a|s) = −½ Σ_j z_j² − Σ_j log σ_j − (d/2) log 2π,   z_j = (a_j − μ_j) / σ_j
    //   H = Σ_j log σ_j + d (½ + ½ log 2π)
    const auto log_std = parameters.segment(log_std_offset_, action_size_);
    tape.inverse_std = (-log_std).unaryExpr(exp_of);
    tape.standardized_actions =
        ((actions - head_output).array().colwise() * tape.inverse_std.array()).matrix();
    const float log_std_sum = log_std.sum();
    const auto dims = static_cast<float>(action_size_);
    tape.log_prob = -0.5f * tape.standardized_actions.colwise().squaredNorm();
    tape.log_prob.array() -= log_std_sum + dims * kHalfLogTwoPi;
    tape.entropy.setConstant(batch, log_std_sum + dims * (0.5f + kHalfLogTwoPi));
    return;
  }
  // Categorical over softmax(logits): log π(a|s) = log p_a, H = −Σ_k p_k log p_k, with
  // log p = logits − logsumexp(logits), shifted by the maximum for stability.
  tape.log_probabilities.resize(head_output.rows(), batch);
  tape.probabilities.resize(head_output.rows(), batch);
  tape.choices.resize(static_cast<std::size_t>(batch));
  tape.log_prob.resize(batch);
  tape.entropy.resize(batch);
  for (int64_t i = 0; i < batch; ++i) {
    const auto logits = head_output.col(i).array();
    const float max = logits.maxCoeff();
    const float log_sum = max + std::log((logits - max).unaryExpr(exp_of).sum());
    auto log_p = tape.log_probabilities.col(i).array();
    log_p = logits - log_sum;
    auto p = tape.probabilities.col(i).array();
    p = log_p.unaryExpr(exp_of);
    const auto choice = static_cast<int64_t>(actions(0, i));
    tape.choices[static_cast<std::size_t>(i)] = choice;
    tape.log_prob[i] = log_p[choice];
    tape.entropy[i] = -(p * log_p).sum();
  }
}

void DenseActorCritic::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                                const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                                const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  const auto run = [&](const Placed& network, Tape::Pass& pass,
                       const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                       Eigen::MatrixXf* input_gradient) {
    network.mlp.backward(segment(parameters, network.offset, network.mlp), pass.tape,
                         output_gradient,
                         parameter_gradient.segment(network.offset, network.mlp.parameter_count()),
                         input_gradient, pass.scratch);
  };
  distribution_backward(log_prob_gradient, entropy_gradient, tape, parameter_gradient);
  run(policy_head_, tape.policy_head, tape.head_gradient,
      policy_trunk_ ? &tape.policy_latent_gradient : nullptr);
  const bool value_needs_latent =
      shared_trunk_ ? policy_trunk_.has_value() : value_trunk_.has_value();
  run(value_head_, tape.value_head, as_matrix(value_gradient),
      value_needs_latent ? &tape.value_latent_gradient : nullptr);
  // A shared trunk receives the sum of both heads' gradients.
  if (shared_trunk_ && policy_trunk_) tape.policy_latent_gradient += tape.value_latent_gradient;
  if (policy_trunk_) run(*policy_trunk_, tape.policy_trunk, tape.policy_latent_gradient, nullptr);
  if (value_trunk_) run(*value_trunk_, tape.value_trunk, tape.value_latent_gradient, nullptr);
}

void DenseActorCritic::distribution_backward(
    const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
    const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient, Tape& tape,
    Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  const Eigen::MatrixXf& head_output = tape.policy_head.tape.output();
  const int64_t batch = head_output.cols();
  tape.head_gradient.resize(head_output.rows(), batch);
  if (!discrete_) {
    // ∂log π/∂μ_j = z_j / σ_j,  ∂log π/∂log σ_j = z_j² − 1,  ∂H/∂log σ_j = 1 (see the forward).
    const Eigen::MatrixXf& z = tape.standardized_actions;
    tape.head_gradient =
        ((z.array().colwise() * tape.inverse_std.array()).rowwise() * log_prob_gradient.array())
            .matrix();
    auto log_std_gradient = parameter_gradient.segment(log_std_offset_, action_size_);
    log_std_gradient.noalias() +=
        (z.array().square() - 1.0f).matrix() * log_prob_gradient.transpose();
    log_std_gradient.array() += entropy_gradient.sum();
    return;
  }
  // Softmax derivatives: ∂log p_a/∂logit_k = [k = a] − p_k,
  // ∂H/∂logit_k = −p_k (log p_k + H).
  for (int64_t i = 0; i < batch; ++i) {
    const auto log_p = tape.log_probabilities.col(i).array();
    const auto p = tape.probabilities.col(i).array();
    auto gradient = tape.head_gradient.col(i).array();
    gradient = -log_prob_gradient[i] * p - entropy_gradient[i] * p * (log_p + tape.entropy[i]);
    gradient[tape.choices[static_cast<std::size_t>(i)]] += log_prob_gradient[i];
  }
}

}  // namespace tendril::nn
