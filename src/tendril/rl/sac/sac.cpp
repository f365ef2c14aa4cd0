#include "tendril/rl/sac/sac.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

constexpr uint64_t kInitStream = 100;

std::vector<int64_t> actor_sizes(int64_t observation_size, const std::vector<int64_t>& hidden,
                                 int64_t action_size) {
  std::vector<int64_t> sizes{observation_size};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(2 * action_size);
  return sizes;
}

}  // namespace

Sac::Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed)
    : OffPolicyAlgorithm("SAC", env, config.common, seed), config_(config) {
  config_.validate();
  require(env.action_space().is_box(),
          "SAC needs a Box action space, not " + env.action_space().describe(), "SAC");
  const int64_t observations = observation_size();
  const int64_t actions = action_size();
  target_entropy_ = config_.target_entropy.value_or(-static_cast<double>(actions));
  Rng init_rng(seed, kInitStream);
  actor_ = nn::DenseMlp(actor_sizes(observations, config_.common.net_arch, actions),
                        config_.common.activation);
  actor_parameters_.resize(actor_.parameter_count());
  actor_.initialize(actor_parameters_, init_rng);
  actor_gradient_ = Eigen::VectorXf::Zero(actor_.parameter_count());
  const double learning_rate = config_.common.learning_rate.initial;
  actor_optimizer_ = nn::Adam(actor_.parameter_count(), {learning_rate});
  critics_ = QCritics(2, observations, actions, config_.common.critic_arch(),
                      config_.common.activation, learning_rate, init_rng);
  log_ent_coef_ = Eigen::VectorXf::Constant(1, static_cast<float>(std::log(config_.ent_coef)));
  ent_coef_optimizer_ = nn::Adam(1, {learning_rate});
}

double Sac::entropy_coefficient() const { return std::exp(static_cast<double>(log_ent_coef_[0])); }

void Sac::sample_policy(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                        PolicySample& sample) const {
  actor_.forward(actor_parameters_, observations, sample.tape);
  Eigen::MatrixXf& noise = sample.distribution.noise;
  noise.resize(action_size(), observations.cols());
  for (Eigen::Index i = 0; i < noise.size(); ++i)
    noise.data()[i] = static_cast<float>(rng.normal());
  sample.distribution.evaluate(sample.tape.output());
}

void Sac::act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
              Eigen::MatrixXf& actions) {
  if (mode != ActMode::kDeterministic) {
    PolicySample sample;
    sample_policy(observations, rng, sample);
    actions = sample.distribution.actions;
    return;
  }
  actor_.forward(actor_parameters_, observations, act_tape_);
  actions = act_tape_.output().topRows(action_size()).array().tanh().matrix();
}

TrainStats Sac::train(int64_t gradient_steps, double progress_remaining) {
  const double learning_rate = config_.common.learning_rate.at(progress_remaining);
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const auto gamma = static_cast<float>(config_.common.gamma);
  const int64_t a = action_size();
  double actor_loss_sum = 0.0, critic_loss_sum = 0.0, ent_coef_sum = 0.0, ent_loss_sum = 0.0;

  for (int64_t step = 0; step < gradient_steps; ++step) {
    buffer().sample(batch_size, sample_rng(), batch_);
    sample_policy(batch_.observations, sample_rng(), current_);

    // α: minimise −log α · (log π + H̄) (eq. 18), with α taken before its own step, as SB3.
    const auto ent_coef = static_cast<float>(entropy_coefficient());
    if (config_.auto_entropy) {
      const double mean_term =
          (current_.distribution.log_probs.array() + static_cast<float>(target_entropy_))
              .cast<double>()
              .mean();
      ent_loss_sum += -static_cast<double>(log_ent_coef_[0]) * mean_term;
      ent_coef_optimizer_.set_learning_rate(learning_rate);
      ent_coef_optimizer_.step(log_ent_coef_,
                               Eigen::VectorXf::Constant(1, static_cast<float>(-mean_term)));
    }
    ent_coef_sum += ent_coef;

    // Critic targets: y = r + γ (1 − d) (min_i Q̄_i(s', a') − α log π(a'|s')), a' ~ π(·|s')  (eq. 3,
    // 5)
    sample_policy(batch_.next_observations, sample_rng(), next_);
    concatenate_rows(batch_.next_observations, next_.distribution.actions, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/true);
    Eigen::VectorXf targets = (critics_.values().colwise().minCoeff().transpose().array() -
                               ent_coef * next_.distribution.log_probs.array())
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
    critics_.step(learning_rate);

    // Actor step on mean(α log π(a|s) − min_i Q_i(s, a)), a = tanh(μ + σ ε)  (eq. 12), through
    // the just-updated critics.
    concatenate_rows(batch_.observations, current_.distribution.actions, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false);
    const Eigen::MatrixXf& q = critics_.values();
    value_gradient_.setZero(q.rows(), q.cols());
    double min_q_sum = 0.0;
    for (Eigen::Index i = 0; i < q.cols(); ++i) {
      Eigen::Index argmin;
      min_q_sum += q.col(i).minCoeff(&argmin);
      value_gradient_(argmin, i) = -inverse_batch;
    }
    actor_loss_sum += ent_coef * static_cast<double>(current_.distribution.log_probs.mean()) -
                      min_q_sum / static_cast<double>(batch_size);
    critics_.backward(value_gradient_, /*parameters=*/false, &input_gradient_);

    current_.distribution.head_gradient(current_.tape.output(), input_gradient_.bottomRows(a),
                                        ent_coef, actor_output_gradient_);
    actor_.backward(actor_parameters_, current_.tape, actor_output_gradient_, actor_gradient_,
                    nullptr, actor_scratch_);
    actor_optimizer_.set_learning_rate(learning_rate);
    actor_optimizer_.step(actor_parameters_, actor_gradient_);
    actor_gradient_.setZero();

    count_update();
    if (gradient_updates() % config_.target_update_interval == 0) {
      critics_.update_target(config_.common.tau);
    }
  }
  const auto n = static_cast<double>(gradient_steps);
  TrainStats stats{{"train/actor_loss", actor_loss_sum / n},
                   {"train/critic_loss", critic_loss_sum / n},
                   {"train/ent_coef", ent_coef_sum / n},
                   {"train/learning_rate", learning_rate}};
  if (config_.auto_entropy) stats.emplace_back("train/ent_coef_loss", ent_loss_sum / n);
  return stats;
}

void Sac::save_state(CheckpointWriter& writer) const {
  writer.write_floats("actor_parameters", actor_parameters_);
  save_adam(writer, "actor_adam", actor_optimizer_);
  critics_.save(writer, "critics");
  writer.write_floats("log_ent_coef", log_ent_coef_);
  save_adam(writer, "ent_coef_adam", ent_coef_optimizer_);
}

std::function<void()> Sac::prepare_load(CheckpointReader& reader) {
  Eigen::VectorXf actor = reader.read_floats("actor_parameters", actor_parameters_.size());
  auto install_actor_adam =
      prepare_adam(reader, "actor_adam", actor_optimizer_, actor_parameters_.size());
  auto install_critics = critics_.prepare_load(reader, "critics");
  Eigen::VectorXf log_ent_coef = reader.read_floats("log_ent_coef", 1);
  auto install_ent_adam = prepare_adam(reader, "ent_coef_adam", ent_coef_optimizer_, 1);
  return [=, this] {
    actor_parameters_ = actor;
    install_actor_adam();
    install_critics();
    log_ent_coef_ = log_ent_coef;
    install_ent_adam();
  };
}

}  // namespace tendril::rl
