#include "tendril/rl/ppo/ppo.hpp"

#include <algorithm>

#include "tendril/nn/gradient.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/ppo/ppo_loss.hpp"
#include "tendril/rl/rollout_minibatches.hpp"

namespace tendril::rl {

namespace {

// Sums over minibatches of the logged statistics.
struct StatisticSums {
  double policy_loss = 0.0, value_loss = 0.0, entropy_loss = 0.0;
  double approx_kl = 0.0, clip_fraction = 0.0;
  double last_loss = 0.0;

  void add(const PpoLossTerms& terms) {
    policy_loss += terms.policy_loss;
    value_loss += terms.value_loss;
    entropy_loss += terms.entropy_loss;
    approx_kl += terms.approx_kl;
    clip_fraction += terms.clip_fraction;
    last_loss = terms.loss;
  }
};

}  // namespace

Ppo::Ppo(envs::VecEnv& env, const PpoConfig& config, uint64_t seed)
    : OnPolicyAlgorithm("PPO", env, config.common, seed), config_(config) {
  config_.validate();
  nn::Adam::Options options;
  options.learning_rate = config_.learning_rate.initial;
  options.epsilon = config_.adam_epsilon;
  if (config_.vf_learning_rate) {
    const int64_t policy_count = network().policy_parameter_count();
    optimizer_ = nn::Adam(policy_count, options);
    options.learning_rate = config_.vf_learning_rate->initial;
    value_optimizer_ = nn::Adam(parameters().size() - policy_count, options);
  } else {
    optimizer_ = nn::Adam(parameters().size(), options);
  }
  gradient_ = Eigen::VectorXf::Zero(parameters().size());
}

void Ppo::adam_step(Eigen::VectorXf& parameters) {
  if (!config_.vf_learning_rate) {
    optimizer_.step(parameters, gradient_);
    return;
  }
  const int64_t policy_count = network().policy_parameter_count();
  const int64_t value_count = parameters.size() - policy_count;
  optimizer_.step(parameters.head(policy_count), gradient_.head(policy_count));
  value_optimizer_.step(parameters.tail(value_count), gradient_.tail(value_count));
}

// One PPO update (Schulman et al. 2017, Algorithm 1): optimise the surrogate
//   L^{CLIP+VF+S}(θ) = Ê_t[ L^CLIP_t(θ) − c₁ L^VF_t(θ) + c₂ S[π_θ](s_t) ]        (eq. 9)
// by minibatch Adam over K epochs of the rollout just collected. Forward and backward passes
// are written out by hand (nn::ActorCritic, ppo_loss) over the policy's flat parameters.
TrainStats Ppo::train(double progress_remaining) {
  const double learning_rate = config_.learning_rate.at(progress_remaining);
  const PpoLossSettings settings{.clip_range = config_.clip_range.at(progress_remaining),
                                 .clip_range_vf = config_.clip_range_vf,
                                 .ent_coef = config_.ent_coef,
                                 .vf_coef = config_.vf_coef};
  optimizer_.set_learning_rate(learning_rate);
  const double vf_learning_rate =
      config_.vf_learning_rate ? config_.vf_learning_rate->at(progress_remaining) : learning_rate;
  if (config_.vf_learning_rate) value_optimizer_.set_learning_rate(vf_learning_rate);
  const nn::ActorCritic& network = this->network();
  Eigen::VectorXf& parameters = this->parameters();
  nn::ActorCritic::Tape tape;
  PpoSampleGradients sample_gradients;
  RolloutMinibatches minibatches(buffer(), config_.batch_size);

  StatisticSums sums;
  int64_t updates = 0;
  bool stopped_early = false;
  for (int64_t epoch = 0; epoch < config_.n_epochs && !stopped_early; ++epoch) {
    minibatches.shuffle(shuffle_rng(), config_.common.normalize_advantage);
    for (int64_t index = 0; index < minibatches.count(); ++index) {
      const RolloutMinibatch batch = minibatches[index];
      network.evaluate(parameters, batch.observations, batch.actions, tape);
      const PpoLossTerms terms =
          ppo_loss(batch, tape.log_prob, tape.entropy, tape.value, settings, sample_gradients);
      sums.add(terms);
      ++updates;
      if (config_.target_kl && terms.approx_kl > 1.5 * *config_.target_kl) {
        stopped_early = true;
        break;
      }
      gradient_.setZero();
      network.backward(parameters, tape, sample_gradients.log_prob, sample_gradients.entropy,
                       sample_gradients.value, gradient_);
      if (config_.max_grad_norm) nn::clip_grad_norm(gradient_, *config_.max_grad_norm);
      adam_step(parameters);
    }
  }

  const double count = static_cast<double>(std::max<int64_t>(updates, 1));
  TrainStats stats = {
      {"train/policy_gradient_loss", sums.policy_loss / count},
      {"train/value_loss", sums.value_loss / count},
      {"train/entropy_loss", sums.entropy_loss / count},
      {"train/approx_kl", sums.approx_kl / count},
      {"train/clip_fraction", sums.clip_fraction / count},
      {"train/loss", sums.last_loss},
      {"train/explained_variance", explained_variance(buffer())},
      {"train/n_updates", static_cast<double>(updates)},
      {"train/clip_range", settings.clip_range},
      {"train/learning_rate", learning_rate},
  };
  if (config_.vf_learning_rate) stats.emplace_back("train/vf_learning_rate", vf_learning_rate);
  if (!network.spec().discrete) {
    const auto log_std = parameters.segment(network.log_std_offset(), network.spec().action_size);
    stats.emplace_back("train/std", log_std.array().exp().cast<double>().mean());
  }
  return stats;
}

void Ppo::write_optimizers(ArchiveWriter& writer) const {
  save_adam(writer, "adam", optimizer_);
  if (config_.vf_learning_rate) save_adam(writer, "adam_value", value_optimizer_);
}

std::function<void()> Ppo::read_optimizers(const ArchiveReader& reader) {
  if (!config_.vf_learning_rate) {
    return prepare_adam(reader, "adam", optimizer_, parameters().size());
  }
  const int64_t policy_count = network().policy_parameter_count();
  auto install_policy = prepare_adam(reader, "adam", optimizer_, policy_count);
  auto install_value =
      prepare_adam(reader, "adam_value", value_optimizer_, parameters().size() - policy_count);
  return [install_policy, install_value] {
    install_policy();
    install_value();
  };
}

}  // namespace tendril::rl
