#include "tendril/rl/dqn/dqn.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

constexpr uint64_t kInitStream = 100;

}  // namespace

Dqn::Dqn(envs::VecEnv& env, const DqnConfig& config, uint64_t seed)
    : OffPolicyAlgorithm("DQN", env, config.common, seed), config_(config) {
  config_.validate();
  require(env.action_space().is_discrete(),
          "DQN needs a Discrete action space, not " + env.action_space().describe(), "DQN");
  actions_count_ = env.action_space().n();
  std::vector<int64_t> sizes{observation_size()};
  sizes.insert(sizes.end(), config_.common.net_arch.begin(), config_.common.net_arch.end());
  sizes.push_back(actions_count_);
  q_network_ = nn::DenseMlp(sizes, config_.common.activation);
  parameters_.resize(q_network_.parameter_count());
  Rng init_rng(seed, kInitStream);
  q_network_.initialize(parameters_, init_rng);
  target_ = parameters_;
  gradient_ = Eigen::VectorXf::Zero(q_network_.parameter_count());
  optimizer_ = nn::Adam(q_network_.parameter_count(), {config_.common.learning_rate.initial});
  exploration_rate_ = config_.exploration_initial_eps;
}

void Dqn::act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
              Eigen::MatrixXf& actions) {
  q_network_.forward(parameters_, observations, tape_);
  actions.resize(1, observations.cols());
  for (Eigen::Index i = 0; i < observations.cols(); ++i) {
    Eigen::Index best;
    tape_.output().col(i).maxCoeff(&best);
    actions(0, i) = static_cast<float>(best);
    if (mode != ActMode::kDeterministic && rng.uniform() < exploration_rate_) {
      actions(0, i) = static_cast<float>(rng.below(static_cast<uint64_t>(actions_count_)));
    }
  }
}

void Dqn::after_step() {
  // ε: linear from the initial to the final value over the first `exploration_fraction` of
  // the budget, then constant (SB3's get_linear_fn).
  const double elapsed = 1.0 - progress_remaining();
  const double fraction = std::min(elapsed / config_.exploration_fraction, 1.0);
  exploration_rate_ = config_.exploration_initial_eps +
                      fraction * (config_.exploration_final_eps - config_.exploration_initial_eps);
  // The target update period counts vector-env steps, as SB3's.
  ++env_steps_;
  const int64_t period = std::max<int64_t>(config_.target_update_interval / num_envs(), 1);
  if (env_steps_ % period == 0) {
    const auto tau = static_cast<float>(config_.common.tau);
    target_ = (1.0f - tau) * target_ + tau * parameters_;
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
    loss_sum += dqn_loss(q_network_, parameters_, target_, batch_, config_.common.gamma,
                         config_.double_q, loss_workspace_, gradient_);
    if (config_.max_grad_norm) {
      // torch.nn.utils.clip_grad_norm_: scale by max / (‖g‖ + 1e-6) when that is below 1.
      const double norm = gradient_.norm();
      const double scale = *config_.max_grad_norm / (norm + 1e-6);
      if (scale < 1.0) gradient_ *= static_cast<float>(scale);
    }
    optimizer_.step(parameters_, gradient_);
  }
  return {{"train/loss", loss_sum / static_cast<double>(gradient_steps)},
          {"train/learning_rate", learning_rate},
          {"rollout/exploration_rate", exploration_rate_}};
}

void Dqn::save_state(CheckpointWriter& writer) const {
  writer.write_floats("q_parameters", parameters_);
  writer.write_floats("q_target", target_);
  save_adam(writer, "q_adam", optimizer_);
  writer.write_int("env_steps", env_steps_);
  writer.write_double("exploration_rate", exploration_rate_);
}

std::function<void()> Dqn::prepare_load(CheckpointReader& reader) {
  const auto count = parameters_.size();
  Eigen::VectorXf parameters = reader.read_floats("q_parameters", count);
  Eigen::VectorXf target = reader.read_floats("q_target", count);
  auto install_adam = prepare_adam(reader, "q_adam", optimizer_, count);
  const int64_t env_steps = reader.read_int("env_steps");
  const double exploration_rate = reader.read_double("exploration_rate");
  return [=, this] {
    parameters_ = parameters;
    target_ = target;
    install_adam();
    env_steps_ = env_steps;
    exploration_rate_ = exploration_rate;
  };
}

}  // namespace tendril::rl
