#include "tendril/rl/ppo/ppo.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/rl/buffer_tensors.hpp"
#include "tendril/rl/minibatches.hpp"

namespace tendril::rl {

namespace {

// Standardises the advantages of each minibatch of `batch_size` consecutive rows in place,
// Â ← (Â − mean) / (std + 1e-8) with the unbiased std, as SB3 does per minibatch; a minibatch of
// one row is left as it is. One pass in double over the epoch's shuffled rows instead of a few
// tensor operations per minibatch.
void normalize_per_minibatch(torch::Tensor& advantages, int64_t batch_size) {
  float* values = advantages.data_ptr<float>();
  const int64_t size = advantages.numel();
  for (int64_t start = 0; start < size; start += batch_size) {
    const int64_t end = std::min(start + batch_size, size);
    const auto n = static_cast<double>(end - start);
    if (end - start < 2) continue;
    double sum = 0.0;
    for (int64_t i = start; i < end; ++i) sum += values[i];
    const double mean = sum / n;
    double squares = 0.0;
    for (int64_t i = start; i < end; ++i) squares += (values[i] - mean) * (values[i] - mean);
    const double scale = 1.0 / (std::sqrt(squares / (n - 1.0)) + 1e-8);
    for (int64_t i = start; i < end; ++i)
      values[i] = static_cast<float>((values[i] - mean) * scale);
  }
}

// Sums over minibatches of the logged statistics, read straight from the (CPU, contiguous)
// tensors: a tensor operation or `.item()` per statistic costs more than the statistic.
struct StatisticSums {
  double policy_loss = 0.0, value_loss = 0.0, entropy_loss = 0.0;
  double approx_kl = 0.0, clip_fraction = 0.0;
  double last_loss = 0.0;

  static double scalar(const torch::Tensor& tensor) { return tensor.data_ptr<float>()[0]; }

  // Adds one minibatch; returns its approximate KL(π_old ‖ π_θ) ≈ Ê[(r − 1) − log r], an
  // unbiased low-variance estimator (Schulman, "Approximating KL divergence", 2020), as SB3.
  double add(const torch::Tensor& ratio, const torch::Tensor& log_ratio, double clip_range,
             const torch::Tensor& policy, const torch::Tensor& value, const torch::Tensor& entropy,
             const torch::Tensor& loss) {
    const torch::Tensor ratio_rows = ratio.contiguous(), log_ratio_rows = log_ratio.contiguous();
    const float* r = ratio_rows.data_ptr<float>();
    const float* log_r = log_ratio_rows.data_ptr<float>();
    const int64_t n = ratio.numel();
    double kl = 0.0;
    int64_t clipped = 0;
    for (int64_t i = 0; i < n; ++i) {
      kl += (r[i] - 1.0) - log_r[i];
      clipped += std::abs(r[i] - 1.0) > clip_range ? 1 : 0;
    }
    kl /= static_cast<double>(n);
    approx_kl += kl;
    clip_fraction += static_cast<double>(clipped) / static_cast<double>(n);
    policy_loss += scalar(policy);
    value_loss += scalar(value);
    entropy_loss += scalar(entropy);
    last_loss = scalar(loss);
    return kl;
  }
};

}  // namespace

Ppo::Ppo(envs::VecEnv& env, const PpoConfig& config, uint64_t seed)
    : OnPolicyAlgorithm("PPO", env, config.common, seed), config_(config) {
  config_.validate();
  optimizer_ = make_optimizer(mutable_policy());
}

std::shared_ptr<nn::FlatAdam> Ppo::make_optimizer(nn::ActorCritic& policy) const {
  nn::FlatAdam::Options options;
  options.learning_rate = config_.learning_rate.initial;
  options.epsilon = config_.adam_epsilon;
  return std::make_shared<nn::FlatAdam>(policy->parameters(), options);
}

// One PPO update (Schulman et al. 2017, Algorithm 1): optimise the surrogate
//   L^{CLIP+VF+S}(θ) = Ê_t[ L^CLIP_t(θ) − c₁ L^VF_t(θ) + c₂ S[π_θ](s_t) ]        (eq. 9)
// by minibatch Adam over K epochs of the rollout just collected.
TrainStats Ppo::train(double progress_remaining) {
  const double learning_rate = config_.learning_rate.at(progress_remaining);
  const double clip_range = config_.clip_range.at(progress_remaining);
  optimizer_->set_learning_rate(learning_rate);
  const BufferTensors rollout(buffer());
  const int64_t size = rollout.size();

  StatisticSums sums;
  int64_t minibatches = 0;
  bool stopped_early = false;
  for (int64_t epoch = 0; epoch < config_.n_epochs && !stopped_early; ++epoch) {
    // The rollout gathered once in this epoch's random order; minibatches are consecutive rows.
    BufferTensors::Batch shuffled = rollout.select(random_permutation(size, shuffle_rng()));
    if (config_.common.normalize_advantage) {
      normalize_per_minibatch(shuffled.advantages, config_.batch_size);
    }
    for (int64_t start = 0; start < size; start += config_.batch_size) {
      const BufferTensors::Batch batch =
          shuffled.rows(start, std::min(start + config_.batch_size, size));
      const torch::Tensor& advantages = batch.advantages;
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
      // mse_loss is Ê[(V − V^targ)²] as one autograd node instead of three.
      const torch::Tensor value_loss = torch::mse_loss(predicted_values, batch.returns);
      // Entropy bonus S, as a loss to minimise.
      const torch::Tensor entropy_loss = -evaluation.entropy.mean();

      // Minimising −L^{CLIP+VF+S}                                                  (eq. 9)
      // A zero entropy coefficient (SB3's default) adds exactly nothing; leaving the term out
      // of the graph saves its backward pass.
      torch::Tensor loss = policy_loss;
      if (config_.ent_coef != 0.0) loss = loss + config_.ent_coef * entropy_loss;
      loss = torch::add(loss, value_loss, config_.vf_coef);

      const double approx_kl =
          sums.add(ratio, log_ratio, clip_range, policy_loss, value_loss, entropy_loss, loss);
      ++minibatches;
      if (config_.target_kl && approx_kl > 1.5 * *config_.target_kl) {
        stopped_early = true;
        break;
      }

      optimizer_->zero_grad();
      loss.backward();
      if (config_.max_grad_norm) optimizer_->parameters().clip_grad_norm(*config_.max_grad_norm);
      optimizer_->step();
    }
  }
  sync_inference();

  const double count = static_cast<double>(std::max<int64_t>(minibatches, 1));
  TrainStats stats = {
      {"train/policy_gradient_loss", sums.policy_loss / count},
      {"train/value_loss", sums.value_loss / count},
      {"train/entropy_loss", sums.entropy_loss / count},
      {"train/approx_kl", sums.approx_kl / count},
      {"train/clip_fraction", sums.clip_fraction / count},
      {"train/loss", sums.last_loss},
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
  std::shared_ptr<nn::FlatAdam> optimizer = make_optimizer(policy);
  reader.read_nested("optimizer",
                     [&](torch::serialize::InputArchive& archive) { optimizer->load(archive); });
  return [this, optimizer] { optimizer_ = optimizer; };
}

}  // namespace tendril::rl
