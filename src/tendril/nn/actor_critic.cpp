#include "tendril/nn/actor_critic.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/nn/gaussian.hpp"

namespace tendril::nn {

namespace {

constexpr const char* kWhere = "nn::ActorCritic";
constexpr double kHiddenGain = 1.4142135623730951;  // √2, SB3's gain for hidden layers
constexpr double kPolicyHeadGain = 0.01;
constexpr double kValueHeadGain = 1.0;

// e^x element by element (these vectors are a handful of actions or choices long).
constexpr auto exp_of = [](float x) { return std::exp(x); };

// A 1 × batch row as the matrix DenseMlp takes, without a copy.
Eigen::Map<const Eigen::MatrixXf> as_matrix(const Eigen::Ref<const Eigen::RowVectorXf>& row) {
  return {row.data(), 1, row.size()};
}

}  // namespace

ActorCritic::ActorCritic(const ActorCriticSpec& spec) : spec_(spec) {
  require(spec.observation_size > 0, "observation size must be positive", kWhere);
  require(spec.action_size > 0, "action size must be positive", kWhere);
  require(!(spec.discrete && spec.policy_output_activation),
          "an output activation applies to a Gaussian mean, not to categorical logits", kWhere);
  int64_t offset = 0;
  const auto place = [&](DenseMlp mlp) {
    Placed placed{std::move(mlp), offset};
    offset += placed.mlp.parameter_count();
    return placed;
  };
  const auto trunk = [&](const std::vector<int64_t>& layers) -> std::optional<Placed> {
    if (layers.empty()) return std::nullopt;
    std::vector<int64_t> sizes{spec.observation_size};
    sizes.insert(sizes.end(), layers.begin(), layers.end());
    return place(DenseMlp::trunk(sizes, spec.activation));
  };
  policy_trunk_ = trunk(spec.policy_layers);
  const int64_t policy_latent =
      spec.policy_layers.empty() ? spec.observation_size : spec.policy_layers.back();
  // A head with an output activation is a one-layer trunk of that activation.
  policy_head_ =
      place(spec.policy_output_activation
                ? DenseMlp::trunk({policy_latent, spec.action_size}, *spec.policy_output_activation)
                : DenseMlp({policy_latent, spec.action_size}, spec.activation));
  if (!spec.discrete) {
    log_std_offset_ = offset;
    offset += spec.action_size;
  }
  policy_parameter_count_ = offset;
  if (!spec.shared_trunk) value_trunk_ = trunk(spec.value_layers);
  const std::vector<int64_t>& value_layers =
      spec.shared_trunk ? spec.policy_layers : spec.value_layers;
  const int64_t value_latent = value_layers.empty() ? spec.observation_size : value_layers.back();
  value_head_ = place(DenseMlp({value_latent, 1}, spec.activation));
  parameter_count_ = offset;
}

void ActorCritic::initialize(Eigen::Ref<Eigen::VectorXf> parameters, Rng& rng) const {
  require(parameters.size() == parameter_count_, "parameter vector has the wrong size", kWhere);
  const auto init = [&](const Placed& network, double output_gain) {
    auto segment = parameters.segment(network.offset, network.mlp.parameter_count());
    if (spec_.orthogonal_init) {
      network.mlp.initialize_orthogonal(segment, kHiddenGain, output_gain, rng);
    } else {
      network.mlp.initialize(segment, rng);
    }
  };
  if (policy_trunk_) init(*policy_trunk_, kHiddenGain);
  if (value_trunk_) init(*value_trunk_, kHiddenGain);
  init(policy_head_, kPolicyHeadGain);
  init(value_head_, kValueHeadGain);
  if (!spec_.discrete) {
    parameters.segment(log_std_offset_, spec_.action_size)
        .setConstant(static_cast<float>(spec_.log_std_init));
  }
}

Eigen::Ref<const Eigen::MatrixXf> ActorCritic::policy_latent(
    const Eigen::Ref<const Eigen::VectorXf>& parameters,
    const Eigen::Ref<const Eigen::MatrixXf>& observations, Tape& tape) const {
  if (!policy_trunk_) return observations;
  policy_trunk_->mlp.forward(
      parameters.segment(policy_trunk_->offset, policy_trunk_->mlp.parameter_count()), observations,
      tape.policy_trunk.tape);
  return tape.policy_trunk.tape.output();
}

void ActorCritic::run_value(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                            const Eigen::Ref<const Eigen::MatrixXf>& observations,
                            const Eigen::Ref<const Eigen::MatrixXf>& policy_latent,
                            Tape& tape) const {
  using ConstRef = Eigen::Ref<const Eigen::MatrixXf>;
  const auto latent = [&]() -> ConstRef {
    if (spec_.shared_trunk) return policy_latent;
    if (!value_trunk_) return observations;
    value_trunk_->mlp.forward(
        parameters.segment(value_trunk_->offset, value_trunk_->mlp.parameter_count()), observations,
        tape.value_trunk.tape);
    return tape.value_trunk.tape.output();
  }();
  value_head_.mlp.forward(parameters.segment(value_head_.offset, value_head_.mlp.parameter_count()),
                          latent, tape.value_head.tape);
  tape.value = tape.value_head.tape.output().row(0);
}

void ActorCritic::act(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                      const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                      Rng& rng, Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs,
                      Tape& tape) const {
  policy_head_.mlp.forward(
      parameters.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
      policy_latent(parameters, observations, tape), tape.policy_head.tape);
  const Eigen::MatrixXf& head = tape.policy_head.tape.output();
  const Eigen::Index batch = head.cols();
  actions.resize(action_dims(), batch);
  log_probs.resize(batch);
  if (spec_.discrete) {
    // Categorical over the logits: sample by inverting the cumulative distribution.
    for (Eigen::Index j = 0; j < batch; ++j) {
      const auto logits = head.col(j);
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
  const auto log_std = parameters.segment(log_std_offset_, spec_.action_size);
  const double constant =
      -log_std.cast<double>().sum() - static_cast<double>(spec_.action_size) * kHalfLogTwoPi;
  for (Eigen::Index j = 0; j < batch; ++j) {
    double squared_norm = 0.0;
    for (Eigen::Index i = 0; i < spec_.action_size; ++i) {
      const double epsilon = deterministic ? 0.0 : rng.normal();
      actions(i, j) = static_cast<float>(head(i, j) + std::exp(log_std[i]) * epsilon);
      squared_norm += epsilon * epsilon;
    }
    log_probs[j] = static_cast<float>(-0.5 * squared_norm + constant);
  }
}

void ActorCritic::value(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                        const Eigen::Ref<const Eigen::MatrixXf>& observations,
                        Eigen::VectorXf& values, Tape& tape) const {
  const Eigen::Ref<const Eigen::MatrixXf> latent =
      spec_.shared_trunk ? policy_latent(parameters, observations, tape) : observations;
  run_value(parameters, observations, latent, tape);
  values = tape.value.transpose();
}

void ActorCritic::evaluate_policy(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                  const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                  const Eigen::Ref<const Eigen::MatrixXf>& actions,
                                  Tape& tape) const {
  policy_head_.mlp.forward(
      parameters.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
      policy_latent(parameters, observations, tape), tape.policy_head.tape);
  distribution_forward(parameters, actions, tape);
}

void ActorCritic::evaluate(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                           const Eigen::Ref<const Eigen::MatrixXf>& observations,
                           const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const {
  evaluate_policy(parameters, observations, actions, tape);
  const Eigen::Ref<const Eigen::MatrixXf> latent =
      policy_trunk_ ? Eigen::Ref<const Eigen::MatrixXf>(tape.policy_trunk.tape.output())
                    : observations;
  run_value(parameters, observations, latent, tape);
}

void ActorCritic::distribution_forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                       const Eigen::Ref<const Eigen::MatrixXf>& actions,
                                       Tape& tape) const {
  const Eigen::MatrixXf& head_output = tape.policy_head.tape.output();
  const int64_t batch = head_output.cols();
  if (!spec_.discrete) {
    // Diagonal Gaussian N(μ, diag σ²) with state-independent log σ:
    //   log π(a|s) = −½ Σ_j z_j² − Σ_j log σ_j − (d/2) log 2π,   z_j = (a_j − μ_j) / σ_j
    //   H = Σ_j log σ_j + d (½ + ½ log 2π)
    const auto log_std = parameters.segment(log_std_offset_, spec_.action_size);
    tape.inverse_std = (-log_std).unaryExpr(exp_of);
    tape.standardized_actions =
        ((actions - head_output).array().colwise() * tape.inverse_std.array()).matrix();
    const float log_std_sum = log_std.sum();
    const auto dims = static_cast<float>(spec_.action_size);
    tape.log_prob = -0.5f * tape.standardized_actions.colwise().squaredNorm();
    tape.log_prob.array() -= log_std_sum + dims * kHalfLogTwoPiF;
    tape.entropy.setConstant(batch, log_std_sum + dims * (0.5f + kHalfLogTwoPiF));
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

void ActorCritic::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                           const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                           const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                           const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                           Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  distribution_backward(log_prob_gradient, entropy_gradient, tape, parameter_gradient);
  // With a shared trunk the value head's input gradient flows on into the policy trunk.
  value_backward(parameters, tape, value_gradient,
                 spec_.shared_trunk ? policy_trunk_.has_value() : value_trunk_.has_value(),
                 parameter_gradient);
  policy_backward(parameters, tape, /*with_value=*/spec_.shared_trunk, parameter_gradient);
}

void ActorCritic::backward_value(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                 const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                                 Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  value_backward(parameters, tape, value_gradient, value_trunk_.has_value(), parameter_gradient);
}

void ActorCritic::value_backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                 const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                                 bool needs_latent_gradient,
                                 Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  value_head_.mlp.backward(
      parameters.segment(value_head_.offset, value_head_.mlp.parameter_count()),
      tape.value_head.tape, as_matrix(value_gradient),
      parameter_gradient.segment(value_head_.offset, value_head_.mlp.parameter_count()),
      needs_latent_gradient ? &tape.value_latent_gradient : nullptr, tape.value_head.scratch);
  if (value_trunk_) {
    value_trunk_->mlp.backward(
        parameters.segment(value_trunk_->offset, value_trunk_->mlp.parameter_count()),
        tape.value_trunk.tape, tape.value_latent_gradient,
        parameter_gradient.segment(value_trunk_->offset, value_trunk_->mlp.parameter_count()),
        nullptr, tape.value_trunk.scratch);
  }
}

void ActorCritic::backward_policy(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                  const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                                  const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                                  Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  distribution_backward(log_prob_gradient, entropy_gradient, tape, parameter_gradient);
  policy_backward(parameters, tape, /*with_value=*/false, parameter_gradient);
}

void ActorCritic::policy_backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                  bool with_value,
                                  Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  policy_head_.mlp.backward(
      parameters.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
      tape.policy_head.tape, tape.head_gradient,
      parameter_gradient.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
      policy_trunk_ ? &tape.policy_latent_gradient : nullptr, tape.policy_head.scratch);
  if (!policy_trunk_) return;
  // A shared trunk receives the sum of both heads' gradients.
  if (with_value) tape.policy_latent_gradient += tape.value_latent_gradient;
  policy_trunk_->mlp.backward(
      parameters.segment(policy_trunk_->offset, policy_trunk_->mlp.parameter_count()),
      tape.policy_trunk.tape, tape.policy_latent_gradient,
      parameter_gradient.segment(policy_trunk_->offset, policy_trunk_->mlp.parameter_count()),
      nullptr, tape.policy_trunk.scratch);
}

void ActorCritic::distribution_backward(
    const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
    const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient, Tape& tape,
    Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  const Eigen::MatrixXf& head_output = tape.policy_head.tape.output();
  const int64_t batch = head_output.cols();
  tape.head_gradient.resize(head_output.rows(), batch);
  if (!spec_.discrete) {
    // ∂log π/∂μ_j = z_j / σ_j,  ∂log π/∂log σ_j = z_j² − 1,  ∂H/∂log σ_j = 1 (see the forward).
    const Eigen::MatrixXf& z = tape.standardized_actions;
    tape.head_gradient =
        ((z.array().colwise() * tape.inverse_std.array()).rowwise() * log_prob_gradient.array())
            .matrix();
    auto log_std_gradient = parameter_gradient.segment(log_std_offset_, spec_.action_size);
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

ActorCritic::Distribution ActorCritic::distribution(
    const Eigen::Ref<const Eigen::VectorXf>& parameters, const Tape& tape) const {
  Distribution result;
  result.head = tape.policy_head.tape.output();
  if (!spec_.discrete) result.log_std = parameters.segment(log_std_offset_, spec_.action_size);
  return result;
}

double ActorCritic::mean_kl(const Distribution& old_distribution,
                            const Distribution& new_distribution) const {
  const Eigen::Index batch = old_distribution.head.cols();
  require(new_distribution.head.cols() == batch, "distributions of different batches", kWhere);
  double total = 0.0;
  if (!spec_.discrete) {
    // KL(N(μo, σo²) ‖ N(μn, σn²)) = Σ_j log σn/σo + (σo² + (μo − μn)²) / (2 σn²) − ½.
    for (Eigen::Index j = 0; j < spec_.action_size; ++j) {
      const double log_old = old_distribution.log_std[j], log_new = new_distribution.log_std[j];
      const double variance_old = std::exp(2.0 * log_old);
      const double inverse_variance_new = std::exp(-2.0 * log_new);
      double squared = 0.0;
      for (Eigen::Index i = 0; i < batch; ++i) {
        const double d = old_distribution.head(j, i) - new_distribution.head(j, i);
        squared += d * d;
      }
      total += batch * (log_new - log_old + 0.5 * variance_old * inverse_variance_new - 0.5) +
               0.5 * squared * inverse_variance_new;
    }
    return total / static_cast<double>(batch);
  }
  // KL(p ‖ q) = Σ_k p_k (log p_k − log q_k) over softmax distributions.
  for (Eigen::Index i = 0; i < batch; ++i) {
    const Eigen::ArrayXd old_logits = old_distribution.head.col(i).cast<double>().array();
    const Eigen::ArrayXd new_logits = new_distribution.head.col(i).cast<double>().array();
    const Eigen::ArrayXd log_p = old_logits - old_logits.maxCoeff() -
                                 std::log((old_logits - old_logits.maxCoeff()).exp().sum());
    const Eigen::ArrayXd log_q = new_logits - new_logits.maxCoeff() -
                                 std::log((new_logits - new_logits.maxCoeff()).exp().sum());
    total += (log_p.exp() * (log_p - log_q)).sum();
  }
  return total / static_cast<double>(batch);
}

void ActorCritic::fisher_vector_product(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                        Tape& tape,
                                        const Eigen::Ref<const Eigen::VectorXf>& tangent,
                                        Eigen::Ref<Eigen::VectorXf> product) const {
  require(tangent.size() == policy_parameter_count_ && product.size() == policy_parameter_count_,
          "a Fisher-vector product spans the policy's parameters", kWhere);
  // u_i = J_i v: the head outputs' change along v, through the trunk when there is one.
  const Eigen::MatrixXf* trunk_tangent = nullptr;
  if (policy_trunk_) {
    policy_trunk_->mlp.jvp(
        parameters.segment(policy_trunk_->offset, policy_trunk_->mlp.parameter_count()),
        tape.policy_trunk.tape,
        tangent.segment(policy_trunk_->offset, policy_trunk_->mlp.parameter_count()), nullptr,
        tape.policy_latent_gradient, tape.policy_trunk.scratch);
    trunk_tangent = &tape.policy_latent_gradient;
  }
  policy_head_.mlp.jvp(parameters.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
                       tape.policy_head.tape,
                       tangent.segment(policy_head_.offset, policy_head_.mlp.parameter_count()),
                       trunk_tangent, tape.head_tangent, tape.policy_head.scratch);
  const Eigen::MatrixXf& u = tape.head_tangent;
  const float inverse_batch = 1.0f / static_cast<float>(u.cols());
  product.setZero();
  if (!spec_.discrete) {
    // Gaussian in (μ, log σ): M = diag(1/σ²) for μ, 2 for each (state-independent) log σ.
    tape.head_gradient =
        (u.array().colwise() * tape.inverse_std.array().square()).matrix() * inverse_batch;
    product.segment(log_std_offset_, spec_.action_size) =
        2.0f * tangent.segment(log_std_offset_, spec_.action_size);
  } else {
    // Softmax in the logits: M = diag(p) − p pᵀ.
    const Eigen::MatrixXf& p = tape.probabilities;
    tape.head_gradient = p.cwiseProduct(u);
    const Eigen::RowVectorXf pu = tape.head_gradient.colwise().sum();
    tape.head_gradient -= (p.array().rowwise() * pu.array()).matrix();
    tape.head_gradient *= inverse_batch;
  }
  policy_backward(parameters, tape, /*with_value=*/false, product);
}

}  // namespace tendril::nn
