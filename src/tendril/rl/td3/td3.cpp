#include "tendril/rl/td3/td3.hpp"

#include "tendril/core/error.hpp"
#include "tendril/nn/gradient.hpp"

namespace tendril::rl {

Td3::Td3(envs::VecEnv& env, const Td3Config& config, uint64_t seed, Td3Variant variant)
    : OffPolicyAlgorithm(variant == Td3Variant::kDdpg ? "DDPG" : "TD3", env, config.common, seed),
      config_(config),
      policy_(env.observation_space(), env.action_space(), config.common.net_arch,
              config.common.activation) {
  config_.validate(name() + " config");
  Rng init_rng = init_stream();
  Eigen::VectorXf& parameters = policy_.parameters();
  policy_.network().initialize(parameters, init_rng);
  actor_target_ = parameters;
  actor_gradient_ = Eigen::VectorXf::Zero(parameters.size());
  actor_optimizer_ = nn::Adam(parameters.size(), {config_.common.learning_rate.initial});
  critics_ = QCritics(config_.n_critics, observation_size(), action_size(),
                      config_.common.critic_arch(), config_.common.activation,
                      config_.critic_learning_rate.value_or(config_.common.learning_rate.initial),
                      init_rng);
  noise_ = ActionNoise(config_.action_noise, num_envs(), action_size());
}

void Td3::explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                  Eigen::MatrixXf& actions) {
  policy_.network().forward(policy_.parameters(), observations, actor_tape_);
  actions = actor_tape_.output();
  if (noise_.active()) {
    noise_.add(actions, rng);
    actions = actions.cwiseMax(-1.0f).cwiseMin(1.0f);
  }
}

TrainStats Td3::train(int64_t gradient_steps, double progress_remaining) {
  const double learning_rate = config_.common.learning_rate.at(progress_remaining);
  const double critic_learning_rate = config_.critic_learning_rate.value_or(learning_rate);
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const auto gamma = static_cast<float>(config_.common.gamma);
  const auto target_noise = static_cast<float>(config_.target_policy_noise);
  const auto noise_clip = static_cast<float>(config_.target_noise_clip);
  double critic_loss_sum = 0.0, actor_loss_sum = 0.0;
  int64_t actor_steps = 0;

  for (int64_t step = 0; step < gradient_steps; ++step) {
    count_update();
    buffer().sample(batch_size, sample_rng(), batch_);

    // y = r + γ (1 − d) min_i Q̄_i(s', clip(π̄(s') + clip(ε, −c, c), −1, 1))  (TD3 eq. 15, 18)
    policy_.network().forward(actor_target_, batch_.next_observations, actor_tape_);
    next_actions_ = actor_tape_.output();
    if (target_noise > 0.0f) {
      for (Eigen::Index i = 0; i < next_actions_.size(); ++i) {
        const float noise = std::clamp(target_noise * static_cast<float>(sample_rng().normal()),
                                       -noise_clip, noise_clip);
        next_actions_.data()[i] = std::clamp(next_actions_.data()[i] + noise, -1.0f, 1.0f);
      }
    }
    concatenate_rows(batch_.next_observations, next_actions_, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/true);
    const Eigen::VectorXf targets =
        (batch_.rewards.array() + gamma * (1.0f - batch_.terminated.array()) *
                                      critics_.values().colwise().minCoeff().transpose().array())
            .matrix();

    // Critic step on Σ_i mean (Q_i(s, a) − y)²  (SB3's TD3 critic loss).
    concatenate_rows(batch_.observations, batch_.actions, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false);
    value_gradient_ = (critics_.values().rowwise() - targets.transpose()) * (2.0f * inverse_batch);
    critic_loss_sum += 0.25 * static_cast<double>(value_gradient_.squaredNorm()) * batch_size;
    critics_.backward(value_gradient_, /*parameters=*/true, nullptr);
    critics_.step(critic_learning_rate);

    // Delayed actor step on −mean Q_1(s, π(s)) (deterministic policy gradient), then targets.
    if (gradient_updates() % config_.policy_delay != 0) continue;
    const nn::DenseMlp& actor = policy_.network();
    Eigen::VectorXf& actor_parameters = policy_.parameters();
    actor.forward(actor_parameters, batch_.observations, actor_tape_);
    concatenate_rows(batch_.observations, actor_tape_.output(), critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false, /*first=*/1);
    actor_loss_sum += -static_cast<double>(critics_.values().row(0).mean());
    value_gradient_.setConstant(1, batch_size, -inverse_batch);
    critics_.backward(value_gradient_, /*parameters=*/false, &input_gradient_);
    actor.backward(actor_parameters, actor_tape_, input_gradient_.bottomRows(action_size()),
                   actor_gradient_, nullptr, actor_scratch_);
    actor_optimizer_.set_learning_rate(learning_rate);
    actor_optimizer_.step(actor_parameters, actor_gradient_);
    actor_gradient_.setZero();
    ++actor_steps;

    critics_.update_target(config_.common.tau);
    nn::polyak_update(actor_target_, actor_parameters, config_.common.tau);
  }
  TrainStats stats{{"train/critic_loss", critic_loss_sum / static_cast<double>(gradient_steps)},
                   {"train/learning_rate", learning_rate}};
  if (actor_steps > 0) {
    stats.emplace_back("train/actor_loss", actor_loss_sum / static_cast<double>(actor_steps));
  }
  return stats;
}

void Td3::write_own_state(ArchiveWriter& writer) const {
  writer.put_floats("actor_parameters", policy_.parameters());
  writer.put_floats("actor_target", actor_target_);
  save_adam(writer, "actor_adam", actor_optimizer_);
  critics_.save(writer, "critics");
  const Eigen::MatrixXf& noise = noise_.state();
  writer.put_floats("noise_state", Eigen::Map<const Eigen::VectorXf>(noise.data(), noise.size()));
}

std::function<void()> Td3::read_own_state(const ArchiveReader& reader) {
  const auto count = policy_.parameters().size();
  Eigen::VectorXf actor = reader.get_floats("actor_parameters", count);
  Eigen::VectorXf target = reader.get_floats("actor_target", count);
  auto install_adam = prepare_adam(reader, "actor_adam", actor_optimizer_, count);
  auto install_critics = critics_.prepare_load(reader, "critics");
  const Eigen::VectorXf noise = reader.get_floats("noise_state", noise_.state().size());
  const Eigen::MatrixXf noise_state =
      Eigen::Map<const Eigen::MatrixXf>(noise.data(), noise_.state().rows(), noise_.state().cols());
  return [=, this] {
    policy_.parameters() = actor;
    actor_target_ = target;
    install_adam();
    install_critics();
    noise_.set_state(noise_state);
  };
}

}  // namespace tendril::rl
