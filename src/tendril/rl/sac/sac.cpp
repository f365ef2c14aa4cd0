#include "tendril/rl/sac/sac.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/nn/gradient.hpp"

namespace tendril::rl {

Sac::Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed)
    : OffPolicyAlgorithm("SAC", env, config.common, seed),
      config_(config),
      policy_(env.observation_space(), env.action_space(), config.common.net_arch,
              config.common.activation, config.use_sde) {
  config_.validate();
  const int64_t actions = action_size();
  target_entropy_ = config_.target_entropy.value_or(-static_cast<double>(actions));
  Rng init_rng = init_stream();
  Eigen::VectorXf& parameters = policy_.parameters();
  const int64_t network = policy_.network().parameter_count();
  policy_.network().initialize(parameters.head(network), init_rng);
  parameters.tail(parameters.size() - network)
      .setConstant(static_cast<float>(config_.log_std_init));
  actor_gradient_ = Eigen::VectorXf::Zero(parameters.size());
  const double learning_rate = config_.common.learning_rate.initial;
  actor_optimizer_ = nn::Adam(parameters.size(), {learning_rate});
  env_exploration_.resize(num_envs());
  critics_ = QCritics(2, observation_size(), actions, config_.common.critic_arch(),
                      config_.common.activation, learning_rate, init_rng);
  log_ent_coef_ = Eigen::VectorXf::Constant(1, static_cast<float>(std::log(config_.ent_coef)));
  ent_coef_optimizer_ = nn::Adam(1, {learning_rate});
}

double Sac::entropy_coefficient() const { return std::exp(static_cast<double>(log_ent_coef_[0])); }

void Sac::explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                  Eigen::MatrixXf& actions) {
  PolicySample sample;
  if (!config_.use_sde) {
    policy_.sample(observations, rng, exploration_, sample);
    actions = sample.gaussian.actions;
    return;
  }
  // Each env keeps its exploration matrix until the next collection starts, or for
  // `sde_sample_freq` steps (SB3's reset_noise).
  if (resample_exploration_ ||
      (config_.sde_sample_freq > 0 && steps_since_resample_ >= config_.sde_sample_freq)) {
    for (auto& matrix : env_exploration_) matrix = policy_.standard_normal_matrix(rng);
    resample_exploration_ = false;
    steps_since_resample_ = 0;
  }
  ++steps_since_resample_;
  actions.resize(action_size(), observations.cols());
  for (Eigen::Index i = 0; i < observations.cols(); ++i) {
    policy_.sample(observations.col(i), rng, env_exploration_[i], sample);
    actions.col(i) = sample.sde.actions;
  }
}

TrainStats Sac::train(int64_t gradient_steps, double progress_remaining) {
  const double learning_rate = config_.common.learning_rate.at(progress_remaining);
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const auto gamma = static_cast<float>(config_.common.gamma);
  double actor_loss_sum = 0.0, critic_loss_sum = 0.0, ent_coef_sum = 0.0, ent_loss_sum = 0.0;
  int64_t actor_steps = 0;

  for (int64_t step = 0; step < gradient_steps; ++step) {
    // The actor and α step when this update's count is a multiple of policy_delay (TD3's rule).
    const bool actor_step = (gradient_updates() + 1) % config_.policy_delay == 0;
    buffer().sample(batch_size, sample_rng(), batch_);
    // gSDE: one exploration matrix for the whole batch, new at every gradient step (SB3).
    if (config_.use_sde) exploration_ = policy_.standard_normal_matrix(sample_rng());
    if (actor_step) policy_.sample(batch_.observations, sample_rng(), exploration_, current_);

    // α steps before the critics, and the critics and the actor use α from before that step,
    // as SB3.
    const auto ent_coef = static_cast<float>(entropy_coefficient());
    if (actor_step) ent_loss_sum += update_entropy_coefficient(learning_rate);
    ent_coef_sum += ent_coef;

    // Critic targets: y = r + γ (1 − d) (min_i Q̄_i(s', a') − α log π(a'|s')), a' ~ π(·|s')
    // (eqs. 3, 5)
    policy_.sample(batch_.next_observations, sample_rng(), exploration_, next_);
    concatenate_rows(batch_.next_observations, policy_.actions_of(next_), critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/true);
    Eigen::VectorXf targets = (critics_.values().colwise().minCoeff().transpose().array() -
                               ent_coef * policy_.log_probs_of(next_).array())
                                  .matrix();
    targets =
        (batch_.rewards.array() + gamma * (1.0f - batch_.terminated.array()) * targets.array())
            .matrix();
    if (config_.q_clip) {
      const auto clip = static_cast<float>(*config_.q_clip);
      targets = targets.cwiseMax(-clip).cwiseMin(clip);
    }

    // Critic step on ½ Σ_i mean (Q_i(s, a) − y)².
    concatenate_rows(batch_.observations, batch_.actions, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false);
    value_gradient_ = (critics_.values().rowwise() - targets.transpose()) * inverse_batch;
    critic_loss_sum += 0.5 * static_cast<double>(value_gradient_.squaredNorm()) * batch_size;
    critics_.backward(value_gradient_, /*parameters=*/true, nullptr);
    critics_.step(learning_rate, config_.max_grad_norm);

    if (actor_step) {
      actor_loss_sum += update_actor(ent_coef, learning_rate);
      ++actor_steps;
      // CleanRL's catch-up: the steps the delay skipped, each on a new sample of the same batch.
      const int64_t extra = config_.compensate_policy_delay ? config_.policy_delay - 1 : 0;
      for (int64_t k = 0; k < extra; ++k) {
        policy_.sample(batch_.observations, sample_rng(), exploration_, current_);
        const auto coefficient = static_cast<float>(entropy_coefficient());
        ent_loss_sum += update_entropy_coefficient(learning_rate);
        actor_loss_sum += update_actor(coefficient, learning_rate);
        ++actor_steps;
      }
    }
    count_update();
    if (gradient_updates() % config_.target_update_interval == 0) {
      critics_.update_target(config_.common.tau);
    }
  }
  const auto n = static_cast<double>(gradient_steps);
  TrainStats stats{{"train/critic_loss", critic_loss_sum / n},
                   {"train/ent_coef", ent_coef_sum / n},
                   {"train/learning_rate", learning_rate}};
  // Means over the actor and α steps; none when this call had none.
  if (actor_steps > 0) {
    const auto m = static_cast<double>(actor_steps);
    stats.insert(stats.begin(), {"train/actor_loss", actor_loss_sum / m});
    if (config_.auto_entropy) stats.emplace_back("train/ent_coef_loss", ent_loss_sum / m);
  }
  return stats;
}

double Sac::update_entropy_coefficient(double learning_rate) {
  if (!config_.auto_entropy) return 0.0;
  // Minimise −log α · (log π + H̄) (eq. 18) over the policy's sample `current_`.
  const double mean_term =
      (policy_.log_probs_of(current_).array() + static_cast<float>(target_entropy_))
          .cast<double>()
          .mean();
  const double loss = -static_cast<double>(log_ent_coef_[0]) * mean_term;
  Eigen::VectorXf gradient = Eigen::VectorXf::Constant(1, static_cast<float>(-mean_term));
  if (config_.max_grad_norm) nn::clip_grad_norm(gradient, *config_.max_grad_norm);
  ent_coef_optimizer_.set_learning_rate(learning_rate);
  ent_coef_optimizer_.step(log_ent_coef_, gradient);
  return loss;
}

double Sac::update_actor(float ent_coef, double learning_rate) {
  // Minimise mean(α log π(a|s) − min_i Q_i(s, a)), a = tanh(μ + σ ε) the sample `current_`
  // (eq. 12), through the just-updated critics.
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const int64_t a = action_size();
  concatenate_rows(batch_.observations, policy_.actions_of(current_), critic_inputs_);
  critics_.forward(critic_inputs_, /*target=*/false);
  const Eigen::MatrixXf& q = critics_.values();
  value_gradient_.setZero(q.rows(), q.cols());
  double min_q_sum = 0.0;
  for (Eigen::Index i = 0; i < q.cols(); ++i) {
    Eigen::Index argmin;
    min_q_sum += q.col(i).minCoeff(&argmin);
    value_gradient_(argmin, i) = -inverse_batch;
  }
  double loss = ent_coef * static_cast<double>(policy_.log_probs_of(current_).mean()) -
                min_q_sum / static_cast<double>(batch_size);
  critics_.backward(value_gradient_, /*parameters=*/false, &input_gradient_);
  if (actor_penalty_ != nullptr) {
    loss += actor_penalty_->add_gradient(batch_.observations, policy_.actions_of(current_),
                                         input_gradient_.bottomRows(a));
  }

  const nn::DenseMlp& actor = policy_.network();
  Eigen::VectorXf& actor_parameters = policy_.parameters();
  const auto network = actor.parameter_count();
  if (config_.use_sde) {
    Eigen::Map<Eigen::MatrixXf> log_std_gradient(actor_gradient_.data() + network,
                                                 policy_.latent_size(), a);
    current_.sde.gradients(current_.tape.output(), policy_.latent_of(current_.tape),
                           policy_.log_std(), input_gradient_.bottomRows(a), ent_coef,
                           actor_output_gradient_, log_std_gradient);
  } else {
    current_.gaussian.head_gradient(current_.tape.output(), input_gradient_.bottomRows(a), ent_coef,
                                    actor_output_gradient_);
  }
  actor.backward(actor_parameters.head(network), current_.tape, actor_output_gradient_,
                 actor_gradient_.head(network), nullptr, actor_scratch_);
  if (config_.max_grad_norm) nn::clip_grad_norm(actor_gradient_, *config_.max_grad_norm);
  actor_optimizer_.set_learning_rate(learning_rate);
  actor_optimizer_.step(actor_parameters, actor_gradient_);
  actor_gradient_.setZero();
  return loss;
}

void Sac::write_own_state(ArchiveWriter& writer) const {
  writer.put_floats("actor_parameters", policy_.parameters());
  save_adam(writer, "actor_adam", actor_optimizer_);
  critics_.save(writer, "critics");
  writer.put_floats("log_ent_coef", log_ent_coef_);
  save_adam(writer, "ent_coef_adam", ent_coef_optimizer_);
}

std::function<void()> Sac::read_own_state(const ArchiveReader& reader) {
  const auto count = policy_.parameters().size();
  Eigen::VectorXf actor = reader.get_floats("actor_parameters", count);
  auto install_actor_adam = prepare_adam(reader, "actor_adam", actor_optimizer_, count);
  auto install_critics = critics_.prepare_load(reader, "critics");
  Eigen::VectorXf log_ent_coef = reader.get_floats("log_ent_coef", 1);
  auto install_ent_adam = prepare_adam(reader, "ent_coef_adam", ent_coef_optimizer_, 1);
  return [=, this] {
    policy_.parameters() = actor;
    install_actor_adam();
    install_critics();
    log_ent_coef_ = log_ent_coef;
    install_ent_adam();
  };
}

}  // namespace tendril::rl
