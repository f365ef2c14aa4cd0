#include "tendril/rl/trpo/trpo.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/rollout_minibatches.hpp"
#include "tendril/rl/trpo/conjugate_gradient.hpp"

namespace tendril::rl {

Trpo::Trpo(envs::VecEnv& env, const TrpoConfig& config, uint64_t seed)
    : OnPolicyAlgorithm("TRPO", env, config.common, seed), config_(config) {
  config_.validate();
  value_offset_ = network().policy_parameter_count();
  value_count_ = network().parameter_count() - value_offset_;
  nn::Adam::Options options;
  options.learning_rate = config_.learning_rate;
  options.epsilon = config_.adam_epsilon;
  value_optimizer_ = nn::Adam(value_count_, options);
}

// One TRPO update (Schulman et al. 2015, section 6 and appendix C):
//   maximise L_θold(θ) = Ê_t[π_θ(a_t|s_t)/π_θold(a_t|s_t) Â_t]            (eq. 14)
//   subject to D̄_KL(θold, θ) = Ê_t[KL(π_θold(·|s_t) ‖ π_θ(·|s_t))] ≤ δ
// by the step θ = θold + β s with s = F⁻¹g (conjugate gradient, F the Fisher matrix = Hessian
// of D̄_KL at θold, g = ∇L) and β = sqrt(2δ / sᵀFs), shrunk until both conditions hold.
TrainStats Trpo::train(double /*progress_remaining*/) {
  const nn::ActorCritic& network = this->network();
  Eigen::VectorXf& parameters = this->parameters();
  const RolloutBuffer& rollout = buffer();
  const auto n = static_cast<Eigen::Index>(rollout.size());
  const Eigen::MatrixXf observations = rollout.observations().transpose();
  const Eigen::MatrixXf actions = rollout.actions().transpose();
  const Eigen::RowVectorXf old_log_probs = rollout.log_probs().transpose();
  Eigen::RowVectorXf advantages = rollout.advantages().transpose();
  if (config_.common.normalize_advantage && n > 1) {
    // (Â − mean) / (std + 1e-8), the unbiased std.
    const double mean = advantages.cast<double>().mean();
    const double variance =
        (advantages.cast<double>().array() - mean).square().sum() / static_cast<double>(n - 1);
    advantages = ((advantages.cast<double>().array() - mean) / (std::sqrt(variance) + 1e-8))
                     .cast<float>()
                     .matrix();
  }
  const auto inverse_n = 1.0f / static_cast<float>(n);
  const int64_t policy_count = value_offset_;

  // Surrogate and its gradient at θold: ∂L/∂log π_t = ratio_t Â_t / N.
  nn::ActorCritic::Tape tape;
  network.evaluate_policy(parameters, observations, actions, tape);
  const Eigen::RowVectorXf ratio = (tape.log_prob - old_log_probs).array().exp().matrix();
  const double old_surrogate = ratio.cwiseProduct(advantages).cast<double>().mean();
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(parameters.size());
  network.backward_policy(parameters, tape, ratio.cwiseProduct(advantages) * inverse_n,
                          Eigen::RowVectorXf::Zero(n), gradient);
  const nn::ActorCritic::Distribution old_distribution = network.distribution(parameters, tape);

  // F v with damping, at θold (the tape of θold's pass is kept).
  Eigen::VectorXf product(policy_count);
  const auto fisher_product = [&](const Eigen::VectorXf& vector) -> Eigen::VectorXf {
    network.fisher_vector_product(parameters, tape, vector, product);
    return product + static_cast<float>(config_.cg_damping) * vector;
  };
  const Eigen::VectorXf policy_gradient = gradient.head(policy_count);
  const Eigen::VectorXf direction =
      conjugate_gradient(fisher_product, policy_gradient, config_.cg_max_steps);
  const double s_f_s = direction.cast<double>().dot(fisher_product(direction).cast<double>());
  const double max_step = std::sqrt(2.0 * config_.target_kl / std::max(s_f_s, 1e-12));

  // Backtracking line search on β: accept the first step that improves the surrogate while
  // keeping the mean KL within δ; otherwise keep θold.
  const Eigen::VectorXf old_parameters = parameters.head(policy_count);
  double coefficient = 1.0, new_surrogate = old_surrogate, new_kl = 0.0;
  bool accepted = false;
  int64_t line_search_steps = 0;
  nn::ActorCritic::Tape candidate;
  for (; line_search_steps < config_.line_search_max_iter; ++line_search_steps) {
    parameters.head(policy_count) =
        old_parameters + static_cast<float>(coefficient * max_step) * direction;
    network.evaluate_policy(parameters, observations, actions, candidate);
    new_surrogate = ((candidate.log_prob - old_log_probs).array().exp() * advantages.array())
                        .cast<double>()
                        .mean();
    new_kl = network.mean_kl(old_distribution, network.distribution(parameters, candidate));
    if (new_kl < config_.target_kl && new_surrogate > old_surrogate) {
      accepted = true;
      break;
    }
    coefficient *= config_.line_search_shrinking_factor;
  }
  if (!accepted) parameters.head(policy_count) = old_parameters;

  const double value_loss = fit_value_function();
  TrainStats stats = {
      {"train/policy_objective", accepted ? new_surrogate : old_surrogate},
      {"train/kl_divergence_loss", accepted ? new_kl : 0.0},
      {"train/value_loss", value_loss},
      {"train/is_line_search_success", accepted ? 1.0 : 0.0},
      {"train/line_search_steps", static_cast<double>(line_search_steps)},
      {"train/explained_variance", explained_variance(rollout)},
      {"train/learning_rate", config_.learning_rate},
  };
  if (!network.spec().discrete) {
    const auto log_std = parameters.segment(network.log_std_offset(), network.spec().action_size);
    stats.emplace_back("train/std", log_std.array().exp().cast<double>().mean());
  }
  return stats;
}

// Value function: minimise Ê[(V_φ(s_t) − V_t^targ)²] by Adam over shuffled minibatches.
double Trpo::fit_value_function() {
  const nn::ActorCritic& network = this->network();
  Eigen::VectorXf& parameters = this->parameters();
  RolloutMinibatches minibatches(buffer(), config_.batch_size);
  nn::ActorCritic::Tape tape;
  Eigen::VectorXf values, gradient = Eigen::VectorXf::Zero(parameters.size());
  double loss_sum = 0.0;
  int64_t steps = 0;
  for (int64_t epoch = 0; epoch < config_.n_critic_updates; ++epoch) {
    minibatches.shuffle(shuffle_rng(), /*normalize_advantages=*/false);
    for (int64_t index = 0; index < minibatches.count(); ++index) {
      const RolloutMinibatch batch = minibatches[index];
      network.value(parameters, batch.observations, values, tape);
      const Eigen::RowVectorXf error = values.transpose() - batch.returns;
      loss_sum += error.cast<double>().squaredNorm() / static_cast<double>(error.size());
      gradient.setZero();
      network.backward_value(parameters, tape, error * (2.0f / static_cast<float>(error.size())),
                             gradient);
      value_optimizer_.step(parameters.segment(value_offset_, value_count_),
                            gradient.segment(value_offset_, value_count_));
      ++steps;
    }
  }
  return loss_sum / static_cast<double>(std::max<int64_t>(steps, 1));
}

void Trpo::write_optimizers(ArchiveWriter& writer) const {
  save_adam(writer, "value_adam", value_optimizer_);
}

std::function<void()> Trpo::read_optimizers(const ArchiveReader& reader) {
  return prepare_adam(reader, "value_adam", value_optimizer_, value_count_);
}

}  // namespace tendril::rl
