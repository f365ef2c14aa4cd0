#include "tendril/rl/ppo/ppo.hpp"

#include <algorithm>
#include <numeric>

#include "tendril/rl/buffer_tensors.hpp"
#include "tendril/rl/minibatches.hpp"

namespace tendril::rl {

Ppo::Ppo(envs::VecEnv& env, const PpoConfig& config, uint64_t seed)
    : OnPolicyAlgorithm("PPO", env, config.common, seed), config_(config) {
  config_.validate();
  optimizer_ = make_optimizer(mutable_policy());
}

std::shared_ptr<torch::optim::Adam> Ppo::make_optimizer(nn::ActorCritic& policy) const {
  return std::make_shared<torch::optim::Adam>(
      policy->parameters(),
      torch::optim::AdamOptions(config_.learning_rate.initial).eps(config_.adam_epsilon));
}

// One PPO update (Schulman et al. 2017, Algorithm 1): optimise the surrogate
//   L^{CLIP+VF+S}(θ) = Ê_t[ L^CLIP_t(θ) − c₁ L^VF_t(θ) + c₂ S[π_θ](s_t) ]        (eq. 9)
// by minibatch Adam over K epochs of the rollout just collected.
TrainStats Ppo::train(double progress_remaining) {
  const double learning_rate = config_.learning_rate.at(progress_remaining);
  const double clip_range = config_.clip_range.at(progress_remaining);
  for (auto& group : optimizer_->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(learning_rate);
  }
  const BufferTensors rollout(buffer());
  const int64_t size = rollout.size();

  double policy_loss_sum = 0.0, value_loss_sum = 0.0, entropy_loss_sum = 0.0;
  double clip_fraction_sum = 0.0, approx_kl_sum = 0.0, last_loss = 0.0;
  int64_t minibatches = 0;
  bool stopped_early = false;
  for (int64_t epoch = 0; epoch < config_.n_epochs && !stopped_early; ++epoch) {
    for (const torch::Tensor& index :
         shuffled_minibatches(size, config_.batch_size, shuffle_rng())) {
      const BufferTensors::Batch batch = rollout.select(index);
      torch::Tensor advantages = batch.advantages;
      if (config_.common.normalize_advantage && index.size(0) > 1) {
        advantages = (advantages - advantages.mean()) / (advantages.std() + 1e-8);
      }
      const auto evaluation = mutable_policy()->evaluate(batch.observations, batch.actions);

      // Probability ratio r_t(θ) = π_θ(a_t|s_t) / π_θold(a_t|s_t)                 (eq. 6)
      const torch::Tensor log_ratio = evaluation.log_prob - batch.old_log_probs;
      const torch::Tensor ratio = torch::exp(log_ratio);
      // L^CLIP = Ê_t[min(r_t Â_t, clip(r_t, 1 − ε, 1 + ε) Â_t)]                    (eq. 7)
      const torch::Tensor surrogate = torch::min(
          ratio * advantages, torch::clamp(ratio, 1.0 - clip_range, 1.0 + clip_range) * advantages);
      const torch::Tensor policy_loss = -surrogate.mean();

      // L^VF = (V_θ(s_t) − V_t^targ)², optionally with V_θ clipped around the old values.
      torch::Tensor predicted_values = evaluation.value;
      if (config_.clip_range_vf) {
        const double clip_vf = *config_.clip_range_vf;
        predicted_values =
            batch.old_values + torch::clamp(evaluation.value - batch.old_values, -clip_vf, clip_vf);
      }
      const torch::Tensor value_loss = (batch.returns - predicted_values).pow(2).mean();
      // Entropy bonus S, as a loss to minimise.
      const torch::Tensor entropy_loss = -evaluation.entropy.mean();

      // Minimising −L^{CLIP+VF+S}                                                  (eq. 9)
      const torch::Tensor loss =
          policy_loss + config_.ent_coef * entropy_loss + config_.vf_coef * value_loss;

      // KL(π_old ‖ π_θ) ≈ Ê[(r − 1) − log r], an unbiased low-variance estimator (Schulman,
      // "Approximating KL divergence", 2020), as SB3.
      double approx_kl;
      {
        torch::NoGradGuard no_grad;
        approx_kl = ((ratio - 1.0) - log_ratio).mean().item<double>();
        clip_fraction_sum +=
            ((ratio - 1.0).abs() > clip_range).to(torch::kFloat).mean().item<double>();
      }
      approx_kl_sum += approx_kl;
      policy_loss_sum += policy_loss.item<double>();
      value_loss_sum += value_loss.item<double>();
      entropy_loss_sum += entropy_loss.item<double>();
      last_loss = loss.item<double>();
      ++minibatches;
      if (config_.target_kl && approx_kl > 1.5 * *config_.target_kl) {
        stopped_early = true;
        break;
      }

      optimizer_->zero_grad();
      loss.backward();
      if (config_.max_grad_norm) {
        torch::nn::utils::clip_grad_norm_(mutable_policy()->parameters(), *config_.max_grad_norm);
      }
      optimizer_->step();
    }
  }
  sync_inference();

  const double count = static_cast<double>(std::max<int64_t>(minibatches, 1));
  TrainStats stats = {
      {"train/policy_gradient_loss", policy_loss_sum / count},
      {"train/value_loss", value_loss_sum / count},
      {"train/entropy_loss", entropy_loss_sum / count},
      {"train/approx_kl", approx_kl_sum / count},
      {"train/clip_fraction", clip_fraction_sum / count},
      {"train/loss", last_loss},
      {"train/explained_variance", explained_variance(buffer())},
      {"train/n_updates", static_cast<double>(minibatches)},
      {"train/clip_range", clip_range},
      {"train/learning_rate", learning_rate},
  };
  if (!mutable_policy()->spec().discrete) {
    stats.emplace_back("train/std", torch::exp(mutable_policy()->log_std()).mean().item<double>());
  }
  return stats;
}

void Ppo::save_optimizers(CheckpointWriter& writer) const {
  torch::serialize::OutputArchive archive;
  optimizer_->save(archive);
  writer.archive().write("optimizer", archive);
}

std::function<void()> Ppo::prepare_load(CheckpointReader& reader, nn::ActorCritic& policy) {
  std::shared_ptr<torch::optim::Adam> optimizer = make_optimizer(policy);
  reader.read_nested("optimizer",
                     [&](torch::serialize::InputArchive& archive) { optimizer->load(archive); });
  return [this, optimizer] { optimizer_ = optimizer; };
}

}  // namespace tendril::rl
