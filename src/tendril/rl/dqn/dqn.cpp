#include "tendril/rl/dqn/dqn.hpp"

#include <algorithm>
#include <cmath>

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
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const auto gamma = static_cast<float>(config_.common.gamma);
  double loss_sum = 0.0;
  for (int64_t step = 0; step < gradient_steps; ++step) {
    count_update();
    buffer().sample(batch_size, sample_rng(), batch_);
    // y = r + γ (1 − d) Q̄(s', a'), a' = argmax Q̄(s', ·) — or argmax Q(s', ·) for double DQN.
    q_network_.forward(target_, batch_.next_observations, next_tape_);
    Eigen::VectorXf next_values(batch_size);
    if (config_.double_q) {
      q_network_.forward(parameters_, batch_.next_observations, tape_);
      for (int64_t i = 0; i < batch_size; ++i) {
        Eigen::Index best;
        tape_.output().col(i).maxCoeff(&best);
        next_values[i] = next_tape_.output()(best, i);
      }
    } else {
      next_values = next_tape_.output().colwise().maxCoeff().transpose();
    }
    const Eigen::VectorXf targets =
        (batch_.rewards.array() + gamma * (1.0f - batch_.terminated.array()) * next_values.array())
            .matrix();

    // Huber loss (smooth L1, δ = 1) between Q(s, a) and y, averaged over the batch.
    q_network_.forward(parameters_, batch_.observations, tape_);
    output_gradient_.setZero(actions_count_, batch_size);
    for (int64_t i = 0; i < batch_size; ++i) {
      const auto action = static_cast<Eigen::Index>(batch_.actions(0, i));
      const float error = tape_.output()(action, i) - targets[i];
      const float magnitude = std::abs(error);
      loss_sum += magnitude < 1.0f ? 0.5 * error * error : magnitude - 0.5;
      output_gradient_(action, i) = std::clamp(error, -1.0f, 1.0f) * inverse_batch;
    }
    q_network_.backward(parameters_, tape_, output_gradient_, gradient_, nullptr, scratch_);
    if (config_.max_grad_norm) {
      // torch.nn.utils.clip_grad_norm_: scale by max / (‖g‖ + 1e-6) when that is below 1.
      const double norm = gradient_.norm();
      const double scale = *config_.max_grad_norm / (norm + 1e-6);
      if (scale < 1.0) gradient_ *= static_cast<float>(scale);
    }
    optimizer_.set_learning_rate(learning_rate);
    optimizer_.step(parameters_, gradient_);
    gradient_.setZero();
  }
  return {{"train/loss", loss_sum / static_cast<double>(gradient_steps * batch_size)},
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
