#include "tendril/rl/dqn/dqn.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"
#include "tendril/nn/gradient.hpp"

namespace tendril::rl {

Dqn::Dqn(envs::VecEnv& env, const DqnConfig& config, uint64_t seed)
    : OffPolicyAlgorithm("DQN", env, config.common, seed),
      config_(config),
      policy_(env.observation_space(), env.action_space(), config.common.net_arch,
              config.common.activation, config.q_bound.value_or(0.0)) {
  config_.validate();
  Eigen::VectorXf& parameters = policy_.parameters();
  Rng init_rng = init_stream();
  policy_.network().initialize(parameters, init_rng);
  target_ = parameters;
  gradient_ = Eigen::VectorXf::Zero(parameters.size());
  optimizer_ = nn::Adam(parameters.size(), {config_.common.learning_rate.initial});
  policy_.set_exploration_rate(config_.exploration_initial_eps);
}

void Dqn::explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                  Eigen::MatrixXf& actions) {
  // ε-greedy with the current ε: the policy's own stochastic action.
  envs::BatchMatrix rows = observations.transpose();
  envs::BatchMatrix chosen;
  policy_.act(rows, /*deterministic=*/false, rng, chosen);
  actions = chosen.transpose();
}

void Dqn::after_step() {
  // ε: linear from the initial to the final value over the first `exploration_fraction` of
  // the budget, then constant (SB3's get_linear_fn).
  const double elapsed = 1.0 - progress_remaining();
  const double fraction = std::min(elapsed / config_.exploration_fraction, 1.0);
  policy_.set_exploration_rate(
      config_.exploration_initial_eps +
      fraction * (config_.exploration_final_eps - config_.exploration_initial_eps));
  // The target update period counts vector-env steps, as SB3's.
  ++env_steps_;
  const int64_t period = std::max<int64_t>(config_.target_update_interval / num_envs(), 1);
  if (env_steps_ % period == 0) {
    nn::polyak_update(target_, policy_.parameters(), config_.common.tau);
  }
}

TrainStats Dqn::train(int64_t gradient_steps, double progress_remaining) {
  const double learning_rate = config_.common.learning_rate.at(progress_remaining);
  optimizer_.set_learning_rate(learning_rate);
  double loss_sum = 0.0;
  for (int64_t step = 0; step < gradient_steps; ++step) {
    count_update();
    buffer().sample(config_.common.batch_size, sample_rng(), batch_);
    gradient_.setZero();
    loss_sum += dqn_loss(policy_.network(), policy_.parameters(), target_, batch_,
                         config_.common.gamma, config_.double_q, policy_.q_bound(),
                         loss_workspace_, gradient_);
    if (config_.max_grad_norm) nn::clip_grad_norm(gradient_, *config_.max_grad_norm);
    optimizer_.step(policy_.parameters(), gradient_);
  }
  return {{"train/loss", loss_sum / static_cast<double>(gradient_steps)},
          {"train/learning_rate", learning_rate},
          {"rollout/exploration_rate", policy_.exploration_rate()}};
}

void Dqn::write_own_state(ArchiveWriter& writer) const {
  writer.put_floats("q_parameters", policy_.parameters());
  writer.put_floats("q_target", target_);
  save_adam(writer, "q_adam", optimizer_);
  writer.put("env_steps", env_steps_);
  writer.put("exploration_rate", policy_.exploration_rate());
}

std::function<void()> Dqn::read_own_state(const ArchiveReader& reader) {
  const auto count = policy_.parameters().size();
  Eigen::VectorXf parameters = reader.get_floats("q_parameters", count);
  Eigen::VectorXf target = reader.get_floats("q_target", count);
  auto install_adam = prepare_adam(reader, "q_adam", optimizer_, count);
  const int64_t env_steps = reader.get_int("env_steps");
  const double exploration_rate = reader.get_double("exploration_rate");
  return [=, this] {
    policy_.parameters() = parameters;
    target_ = target;
    install_adam();
    env_steps_ = env_steps;
    policy_.set_exploration_rate(exploration_rate);
  };
}

}  // namespace tendril::rl
