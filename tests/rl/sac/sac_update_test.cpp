// SAC's training step against an independent LibTorch-autograd implementation of
// Stable-Baselines3's SAC.train (stable_baselines3/sac/sac.py; Haarnoja et al. 2018, "Soft
// Actor-Critic Algorithms and Applications", eqs. 3, 5, 12, 18) on a fixed replay buffer: the
// reported critic, actor and entropy-coefficient losses, and every parameter after a few
// gradient steps — actor, critics and log α after their Adam steps, target critics after Polyak
// averaging. The reference replays the update's random draws (the batch, then ε for s, then ε'
// for s') from a copy of the algorithm's sampling stream, read from a checkpoint.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "envs/scripted_env.hpp"
#include "support/random_replay_buffer.hpp"
#include "support/reference_networks.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/rl/sac/sac.hpp"

namespace tendril::rl {
namespace {

using namespace tendril::testing;

constexpr int64_t kObservations = 3;  // ScriptedEnv's spaces
constexpr int64_t kActions = 2;
constexpr int64_t kHidden = 16;
constexpr int64_t kBatch = 64;
constexpr int64_t kBufferSize = 400;
constexpr int kGradientSteps = 3;
constexpr double kProgress = 0.5;  // of the budget remaining: the linear lr schedule at half

// Exposes the protected training step.
class SacUnderTest : public Sac {
 public:
  using Sac::Sac;
  TrainStats update(int64_t steps, double progress_remaining) {
    return train(steps, progress_remaining);
  }
};

struct Parameters {
  Eigen::VectorXf actor, critics, critics_target, log_ent_coef;
  Rng samples;
};

Parameters read_parameters(const std::filesystem::path& file, int64_t actor_count,
                           int64_t critic_count) {
  const ArchiveReader reader(file, "checkpoint");
  Parameters result;
  result.actor = reader.get_floats("actor_parameters", actor_count);
  result.critics = reader.get_floats("critics_parameters", critic_count);
  result.critics_target = reader.get_floats("critics_target", critic_count);
  result.log_ent_coef = reader.get_floats("log_ent_coef", 1);
  result.samples = reader.get_rng("rng_updates");
  return result;
}

struct Losses {
  double critic = 0.0, actor = 0.0, ent_coef = 0.0, ent_coef_loss = 0.0;
};

// SB3's SAC.train, written with torch modules and autograd.
class ReferenceSac {
 public:
  ReferenceSac(const Parameters& start, double learning_rate, double gamma, double tau,
               bool auto_entropy)
      : actor_(reference_mlp({kObservations, kHidden, kHidden, 2 * kActions}, false)),
        gamma_(gamma),
        tau_(tau),
        auto_entropy_(auto_entropy) {
    const std::vector<int64_t> critic_sizes{kObservations + kActions, kHidden, kHidden, 1};
    for (int i = 0; i < 2; ++i) {
      critics_.push_back(reference_mlp(critic_sizes, false));
      targets_.push_back(reference_mlp(critic_sizes, false));
    }
    EXPECT_EQ(load_flat(*actor_, start.actor), start.actor.size());
    int64_t offset = 0, target_offset = 0;
    for (int i = 0; i < 2; ++i) {
      offset = load_flat(*critics_[i], start.critics, offset);
      target_offset = load_flat(*targets_[i], start.critics_target, target_offset);
    }
    EXPECT_EQ(offset, start.critics.size());
    log_ent_coef_ = torch::tensor({start.log_ent_coef[0]}).requires_grad_(auto_entropy);
    const auto options = torch::optim::AdamOptions(learning_rate);  // SB3: Adam, eps 1e-8
    actor_optimizer_ = std::make_unique<torch::optim::Adam>(actor_->parameters(), options);
    std::vector<torch::Tensor> critic_parameters;
    for (auto& critic : critics_) {
      for (auto& p : critic->parameters()) critic_parameters.push_back(p);
    }
    critic_optimizer_ = std::make_unique<torch::optim::Adam>(critic_parameters, options);
    ent_optimizer_ =
        std::make_unique<torch::optim::Adam>(std::vector<torch::Tensor>{log_ent_coef_}, options);
  }

  // One gradient step on the batch; ε and ε' are the reparameterisation noise for s and s'.
  Losses step(const ReplayBuffer::Batch& batch, const torch::Tensor& noise,
              const torch::Tensor& next_noise, double target_entropy) {
    const torch::Tensor observations = rows_of(batch.observations);
    const torch::Tensor actions = rows_of(batch.actions);
    const torch::Tensor rewards = column_tensor(batch.rewards);
    const torch::Tensor next_observations = rows_of(batch.next_observations);
    const torch::Tensor dones = column_tensor(batch.terminated);
    Losses losses;

    auto [actions_pi, log_prob] = sample(observations, noise);
    torch::Tensor ent_coef = torch::exp(log_ent_coef_.detach());
    if (auto_entropy_) {
      const torch::Tensor ent_coef_loss =
          -(log_ent_coef_ * (log_prob + target_entropy).detach()).mean();
      losses.ent_coef_loss = ent_coef_loss.item<double>();
      ent_optimizer_->zero_grad();
      ent_coef_loss.backward();
      ent_optimizer_->step();
    }
    losses.ent_coef = ent_coef.item<double>();

    torch::Tensor target_q;
    {
      torch::NoGradGuard no_grad;
      auto [next_actions, next_log_prob] = sample(next_observations, next_noise);
      const torch::Tensor next_inputs = torch::cat({next_observations, next_actions}, 1);
      torch::Tensor next_q =
          torch::cat({targets_[0]->forward(next_inputs), targets_[1]->forward(next_inputs)}, 1);
      next_q = std::get<0>(torch::min(next_q, 1, /*keepdim=*/true));
      next_q = next_q - ent_coef * next_log_prob;
      target_q = rewards + (1 - dones) * gamma_ * next_q;
    }
    const torch::Tensor inputs = torch::cat({observations, actions}, 1);
    torch::Tensor critic_loss = torch::zeros({});
    for (auto& critic : critics_) {
      critic_loss = critic_loss + torch::mse_loss(critic->forward(inputs), target_q);
    }
    critic_loss = 0.5 * critic_loss;
    losses.critic = critic_loss.item<double>();
    critic_optimizer_->zero_grad();
    critic_loss.backward();
    critic_optimizer_->step();

    const torch::Tensor pi_inputs = torch::cat({observations, actions_pi}, 1);
    const torch::Tensor q_pi =
        torch::cat({critics_[0]->forward(pi_inputs), critics_[1]->forward(pi_inputs)}, 1);
    const torch::Tensor min_q_pi = std::get<0>(torch::min(q_pi, 1, /*keepdim=*/true));
    const torch::Tensor actor_loss = (ent_coef * log_prob - min_q_pi).mean();
    losses.actor = actor_loss.item<double>();
    actor_optimizer_->zero_grad();
    actor_loss.backward();
    actor_optimizer_->step();

    torch::NoGradGuard no_grad;
    for (int i = 0; i < 2; ++i) {
      const auto online = critics_[i]->parameters();
      auto target = targets_[i]->parameters();
      for (size_t k = 0; k < online.size(); ++k) {
        target[k].mul_(1 - tau_).add_(online[k], tau_);
      }
    }
    return losses;
  }

  Eigen::VectorXf actor() const { return flat_parameters({actor_.get()}); }
  Eigen::VectorXf critics() const {
    return flat_parameters({critics_[0].get(), critics_[1].get()});
  }
  Eigen::VectorXf targets() const {
    return flat_parameters({targets_[0].get(), targets_[1].get()});
  }
  float log_ent_coef() const { return log_ent_coef_.item<float>(); }

 private:
  std::pair<torch::Tensor, torch::Tensor> sample(const torch::Tensor& observations,
                                                 const torch::Tensor& noise) {
    return squashed_gaussian_sample(actor_, observations, noise, kActions);
  }

  torch::nn::Sequential actor_;
  std::vector<torch::nn::Sequential> critics_, targets_;
  torch::Tensor log_ent_coef_;
  std::unique_ptr<torch::optim::Adam> actor_optimizer_, critic_optimizer_, ent_optimizer_;
  double gamma_, tau_;
  bool auto_entropy_;
};

struct Case {
  const char* name;
  const char* ent_coef;  // SB3's ent_coef: auto_<initial> or a fixed number
};

class SacUpdate : public ScratchDirectoryTest, public ::testing::WithParamInterface<Case> {
 protected:
  SacUpdate() : ScratchDirectoryTest("sac_update") {}
};

TEST_P(SacUpdate, MatchesStableBaselines3UpdateWrittenWithAutograd) {
  const double learning_rate = 3e-3, gamma = 0.98, tau = 0.1;
  const std::string algo = "buffer_size: " + std::to_string(kBufferSize) +
                           "\nbatch_size: " + std::to_string(kBatch) +
                           "\nnet_arch: [16, 16]\nlearning_rate: 3e-3\n"
                           "learning_rate_schedule: linear\ngamma: 0.98\ntau: 0.1\nent_coef: " +
                           GetParam().ent_coef + "\n";
  const SacConfig config = SacConfig::from_config(Config::parse(algo));
  envs::ThreadedVecEnv env(1, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
  SacUnderTest agent(env, config, 3);
  testing::write_random_replay_buffer(directory_ / "buffer.bin", kBufferSize, kObservations,
                                      kActions, 21);
  agent.load_replay_buffer(directory_ / "buffer.bin");

  const int64_t actor_count =
      parameter_count(*reference_mlp({kObservations, kHidden, kHidden, 2 * kActions}, false));
  const int64_t critic_count =
      2 * parameter_count(*reference_mlp({kObservations + kActions, kHidden, kHidden, 1}, false));
  agent.save(directory_ / "before.ckpt");
  Parameters start = read_parameters(directory_ / "before.ckpt", actor_count, critic_count);
  ASSERT_TRUE(start.critics.isApprox(start.critics_target));

  ReferenceSac reference(start, learning_rate * kProgress, gamma, tau, config.auto_entropy);
  Losses sums;
  ReplayBuffer::Batch batch;
  for (int step = 0; step < kGradientSteps; ++step) {
    agent.replay_buffer().sample(kBatch, start.samples, batch);
    const torch::Tensor noise = standard_normal(start.samples, kBatch, kActions);
    const torch::Tensor next_noise = standard_normal(start.samples, kBatch, kActions);
    const Losses losses = reference.step(batch, noise, next_noise, -static_cast<double>(kActions));
    sums.critic += losses.critic / kGradientSteps;
    sums.actor += losses.actor / kGradientSteps;
    sums.ent_coef += losses.ent_coef / kGradientSteps;
    sums.ent_coef_loss += losses.ent_coef_loss / kGradientSteps;
  }
  const TrainStats stats = agent.update(kGradientSteps, kProgress);
  agent.save(directory_ / "after.ckpt");
  const Parameters end = read_parameters(directory_ / "after.ckpt", actor_count, critic_count);

  EXPECT_NEAR(stat(stats, "train/critic_loss"), sums.critic, 1e-5 * std::abs(sums.critic));
  EXPECT_NEAR(stat(stats, "train/actor_loss"), sums.actor, 1e-5 * std::abs(sums.actor) + 1e-6);
  EXPECT_NEAR(stat(stats, "train/ent_coef"), sums.ent_coef, 1e-6 * sums.ent_coef);
  EXPECT_NEAR(stat(stats, "train/learning_rate"), learning_rate * kProgress, 1e-12);
  if (config.auto_entropy) {
    EXPECT_NEAR(stat(stats, "train/ent_coef_loss"), sums.ent_coef_loss,
                1e-5 * std::abs(sums.ent_coef_loss) + 1e-7);
  }

  // Each Adam step moves a parameter by about the learning rate; the implementations agree to
  // float rounding, far below that.
  const double step_size = learning_rate * kProgress;
  EXPECT_GT(max_difference(end.actor, start.actor), 0.5 * step_size);
  EXPECT_LT(max_difference(end.actor, reference.actor()), 1e-3 * step_size);
  EXPECT_GT(max_difference(end.critics, start.critics), 0.5 * step_size);
  EXPECT_LT(max_difference(end.critics, reference.critics()), 1e-3 * step_size);
  EXPECT_GT(max_difference(end.critics_target, start.critics_target), 0.1 * tau * step_size);
  EXPECT_LT(max_difference(end.critics_target, reference.targets()),
            1e-3 * tau * step_size + float_rounding(end.critics_target));
  EXPECT_NEAR(end.log_ent_coef[0], reference.log_ent_coef(), 1e-3 * step_size);
  if (config.auto_entropy) {
    EXPECT_GT(std::abs(end.log_ent_coef[0] - start.log_ent_coef[0]), 0.5 * step_size);
  }
}

INSTANTIATE_TEST_SUITE_P(EntropyCoefficient, SacUpdate,
                         ::testing::Values(Case{"Learned", "auto_0.3"}, Case{"Fixed", "0.2"}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace tendril::rl
