#include "tendril/rl/trpo/trpo.hpp"

#include <cmath>

#include "tendril/nn/parameter_vector.hpp"
#include "tendril/rl/buffer_tensors.hpp"
#include "tendril/rl/minibatches.hpp"
#include "tendril/rl/trpo/conjugate_gradient.hpp"

namespace tendril::rl {

Trpo::Trpo(envs::VecEnv& env, const TrpoConfig& config, uint64_t seed)
    : OnPolicyAlgorithm("TRPO", env, config.common, seed), config_(config) {
  config_.validate();
  value_optimizer_ = make_value_optimizer(mutable_policy());
}

std::shared_ptr<torch::optim::Adam> Trpo::make_value_optimizer(nn::ActorCritic& policy) const {
  return std::make_shared<torch::optim::Adam>(
      policy->value_parameters(),
      torch::optim::AdamOptions(config_.learning_rate).eps(config_.adam_epsilon));
}

// One TRPO update (Schulman et al. 2015, section 6 and appendix C):
//   maximise L_θold(θ) = Ê_t[π_θ(a_t|s_t)/π_θold(a_t|s_t) Â_t]            (eq. 14)
//   subject to D̄_KL(θold, θ) = Ê_t[KL(π_θold(·|s_t) ‖ π_θ(·|s_t))] ≤ δ
// by the step θ = θold + β s with s = F⁻¹g (conjugate gradient, F the Fisher matrix = Hessian
// of D̄_KL at θold, g = ∇L) and β = sqrt(2δ / sᵀFs), shrunk until both conditions hold.
TrainStats Trpo::train(double /*progress_remaining*/) {
  const BufferTensors rollout(buffer());
  const BufferTensors::Batch& data = rollout.all();
  torch::Tensor advantages = data.advantages;
  if (config_.common.normalize_advantage && rollout.size() > 1) {
    advantages = (advantages - advantages.mean()) / (advantages.std() + 1e-8);
  }
  const std::vector<torch::Tensor> actor_parameters = mutable_policy()->policy_parameters();

  // Surrogate and mean KL at θold, with the graph kept for the gradient and Fisher products.
  const nn::PolicyDistribution pi = mutable_policy()->distribution(data.observations);
  const nn::PolicyDistribution pi_old = pi.detached();
  const torch::Tensor ratio = torch::exp(pi.log_prob(data.actions) - data.old_log_probs);
  const torch::Tensor surrogate = (ratio * advantages).mean();
  const torch::Tensor mean_kl = pi_old.kl(pi).mean();

  const torch::Tensor gradient =
      nn::flatten(torch::autograd::grad({surrogate}, actor_parameters, {}, /*retain_graph=*/true));
  const torch::Tensor kl_gradient = nn::flatten(torch::autograd::grad(
      {mean_kl}, actor_parameters, {}, /*retain_graph=*/true, /*create_graph=*/true));
  // F v = ∇(∇D̄_KL · v), plus damping for a well-conditioned solve.
  const auto fisher_product = [&](const torch::Tensor& vector) {
    const torch::Tensor product = nn::flatten(torch::autograd::grad(
        {(kl_gradient * vector).sum()}, actor_parameters, {}, /*retain_graph=*/true));
    return product + config_.cg_damping * vector;
  };
  const torch::Tensor direction =
      conjugate_gradient(fisher_product, gradient.detach(), config_.cg_max_steps);
  const double s_f_s = direction.dot(fisher_product(direction)).item<double>();
  const double max_step = std::sqrt(2.0 * config_.target_kl / std::max(s_f_s, 1e-12));

  // Backtracking line search on β: accept the first step that improves the surrogate while
  // keeping the mean KL within δ; otherwise keep θold.
  const torch::Tensor old_parameters = nn::flatten_parameters(actor_parameters);
  const double old_surrogate = surrogate.item<double>();
  double coefficient = 1.0, new_surrogate = old_surrogate, new_kl = 0.0;
  bool accepted = false;
  int64_t line_search_steps = 0;
  {
    torch::NoGradGuard no_grad;
    for (; line_search_steps < config_.line_search_max_iter; ++line_search_steps) {
      nn::assign_parameters(actor_parameters, old_parameters + coefficient * max_step * direction);
      const nn::PolicyDistribution candidate = mutable_policy()->distribution(data.observations);
      new_surrogate =
          (torch::exp(candidate.log_prob(data.actions) - data.old_log_probs) * advantages)
              .mean()
              .item<double>();
      new_kl = pi_old.kl(candidate).mean().item<double>();
      if (new_kl < config_.target_kl && new_surrogate > old_surrogate) {
        accepted = true;
        break;
      }
      coefficient *= config_.line_search_shrinking_factor;
    }
    if (!accepted) nn::assign_parameters(actor_parameters, old_parameters);
  }

  // Value function: minimise Ê[(V_φ(s_t) − V_t^targ)²] by Adam over shuffled minibatches.
  double value_loss_sum = 0.0;
  int64_t value_steps = 0;
  for (int64_t epoch = 0; epoch < config_.n_critic_updates; ++epoch) {
    for (const torch::Tensor& index :
         shuffled_minibatches(rollout.size(), config_.batch_size, shuffle_rng())) {
      const BufferTensors::Batch batch = rollout.select(index);
      const torch::Tensor value_loss =
          (batch.returns - mutable_policy()->value(batch.observations)).pow(2).mean();
      value_optimizer_->zero_grad();
      value_loss.backward();
      value_optimizer_->step();
      value_loss_sum += value_loss.item<double>();
      ++value_steps;
    }
  }
  sync_inference();

  TrainStats stats = {
      {"train/policy_objective", accepted ? new_surrogate : old_surrogate},
      {"train/kl_divergence_loss", accepted ? new_kl : 0.0},
      {"train/value_loss", value_loss_sum / static_cast<double>(std::max<int64_t>(value_steps, 1))},
      {"train/is_line_search_success", accepted ? 1.0 : 0.0},
      {"train/line_search_steps", static_cast<double>(line_search_steps)},
      {"train/explained_variance", explained_variance(buffer())},
      {"train/learning_rate", config_.learning_rate},
  };
  if (!mutable_policy()->spec().discrete) {
    stats.emplace_back("train/std", torch::exp(mutable_policy()->log_std()).mean().item<double>());
  }
  return stats;
}

void Trpo::save_optimizers(CheckpointWriter& writer) const {
  torch::serialize::OutputArchive archive;
  value_optimizer_->save(archive);
  writer.archive().write("value_optimizer", archive);
}

std::function<void()> Trpo::prepare_load(CheckpointReader& reader, nn::ActorCritic& policy) {
  std::shared_ptr<torch::optim::Adam> optimizer = make_value_optimizer(policy);
  reader.read_nested("value_optimizer",
                     [&](torch::serialize::InputArchive& archive) { optimizer->load(archive); });
  return [this, optimizer] { value_optimizer_ = optimizer; };
}

}  // namespace tendril::rl
