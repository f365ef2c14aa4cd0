// TD3's and DDPG's training steps against an independent LibTorch-autograd implementation of
// Stable-Baselines3's TD3.train (stable_baselines3/td3/td3.py; Fujimoto et al. 2018, Algorithm 1:
// target-policy smoothing, clipped double-Q, delayed policy and target updates; DDPG as TD3 with
// one critic, no smoothing and no delay, as SB3 defines it) on a fixed replay buffer: the
// reported losses, the actor and critics after their Adam steps and both targets after Polyak
// averaging. The reference replays the update's random draws (the batch, then the smoothing
// noise) from a copy of the algorithm's sampling stream, read from a checkpoint.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "envs/scripted_env.hpp"
#include "support/random_replay_buffer.hpp"
#include "support/reference_networks.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/rl/td3/td3.hpp"

namespace tendril::rl {
namespace {

using namespace tendril::testing;

constexpr int64_t kObservations = 3;  // ScriptedEnv's spaces
constexpr int64_t kActions = 2;
constexpr int64_t kHidden = 16;
constexpr int64_t kBatch = 64;
constexpr int64_t kBufferSize = 400;
constexpr int kGradientSteps = 4;

class Td3UnderTest : public Td3 {
 public:
  using Td3::Td3;
  TrainStats update(int64_t steps, double progress_remaining) {
    return train(steps, progress_remaining);
  }
};

struct Parameters {
  Eigen::VectorXf actor, actor_target, critics, critics_target;
  Rng samples;
};

Parameters read_parameters(const std::filesystem::path& file, int64_t actor_count,
                           int64_t critic_count) {
  const ArchiveReader reader(file, "checkpoint");
  Parameters result;
  result.actor = reader.get_floats("actor_parameters", actor_count);
  result.actor_target = reader.get_floats("actor_target", actor_count);
  result.critics = reader.get_floats("critics_parameters", critic_count);
  result.critics_target = reader.get_floats("critics_target", critic_count);
  result.samples = reader.get_rng("rng_updates");
  return result;
}

struct Settings {
  const char* name;
  bool ddpg;
  int critics;
  int64_t policy_delay;
  double target_noise, noise_clip;
  double learning_rate, critic_learning_rate;
};

void polyak(torch::nn::Module& target, const torch::nn::Module& online, double tau) {
  torch::NoGradGuard no_grad;
  auto targets = target.parameters();
  const auto onlines = online.parameters();
  for (size_t k = 0; k < targets.size(); ++k) targets[k].mul_(1 - tau).add_(onlines[k], tau);
}

// SB3's TD3.train, written with torch modules and autograd.
class ReferenceTd3 {
 public:
  ReferenceTd3(const Parameters& start, const Settings& settings, double gamma, double tau)
      : settings_(settings), gamma_(gamma), tau_(tau) {
    const std::vector<int64_t> actor_sizes{kObservations, kHidden, kHidden, kActions};
    actor_ = reference_mlp(actor_sizes, false, /*tanh_output=*/true);
    actor_target_ = reference_mlp(actor_sizes, false, true);
    load_flat(*actor_, start.actor);
    load_flat(*actor_target_, start.actor_target);
    const std::vector<int64_t> critic_sizes{kObservations + kActions, kHidden, kHidden, 1};
    int64_t offset = 0, target_offset = 0;
    std::vector<torch::Tensor> critic_parameters;
    for (int i = 0; i < settings.critics; ++i) {
      critics_.push_back(reference_mlp(critic_sizes, false));
      targets_.push_back(reference_mlp(critic_sizes, false));
      offset = load_flat(*critics_[i], start.critics, offset);
      target_offset = load_flat(*targets_[i], start.critics_target, target_offset);
      for (auto& p : critics_[i]->parameters()) critic_parameters.push_back(p);
    }
    EXPECT_EQ(offset, start.critics.size());
    actor_optimizer_ = std::make_unique<torch::optim::Adam>(
        actor_->parameters(), torch::optim::AdamOptions(settings.learning_rate));
    critic_optimizer_ = std::make_unique<torch::optim::Adam>(
        critic_parameters, torch::optim::AdamOptions(settings.critic_learning_rate));
  }

  // One gradient step (`n_updates` counts them, this one included); `noise` is the standard
  // normal draw behind the smoothing noise. Returns the critic loss and, when the actor was
  // updated, sets `actor_loss`.
  double step(const ReplayBuffer::Batch& batch, const torch::Tensor& noise, int64_t n_updates,
              std::optional<double>& actor_loss) {
    const torch::Tensor observations = rows_of(batch.observations);
    const torch::Tensor actions = rows_of(batch.actions);
    const torch::Tensor rewards = column_tensor(batch.rewards);
    const torch::Tensor next_observations = rows_of(batch.next_observations);
    const torch::Tensor dones = column_tensor(batch.terminated);

    torch::Tensor target_q;
    {
      torch::NoGradGuard no_grad;
      const torch::Tensor smoothing =
          (settings_.target_noise * noise).clamp(-settings_.noise_clip, settings_.noise_clip);
      const torch::Tensor next_actions =
          (actor_target_->forward(next_observations) + smoothing).clamp(-1, 1);
      const torch::Tensor next_inputs = torch::cat({next_observations, next_actions}, 1);
      std::vector<torch::Tensor> next_q;
      for (auto& target : targets_) next_q.push_back(target->forward(next_inputs));
      const torch::Tensor min_q = std::get<0>(torch::min(torch::cat(next_q, 1), 1, true));
      target_q = rewards + (1 - dones) * gamma_ * min_q;
    }
    const torch::Tensor inputs = torch::cat({observations, actions}, 1);
    torch::Tensor critic_loss = torch::zeros({});
    for (auto& critic : critics_) {
      critic_loss = critic_loss + torch::mse_loss(critic->forward(inputs), target_q);
    }
    critic_optimizer_->zero_grad();
    critic_loss.backward();
    critic_optimizer_->step();

    if (n_updates % settings_.policy_delay == 0) {
      const torch::Tensor q1 =
          critics_[0]->forward(torch::cat({observations, actor_->forward(observations)}, 1));
      const torch::Tensor loss = -q1.mean();
      actor_loss = loss.item<double>();
      actor_optimizer_->zero_grad();
      loss.backward();
      actor_optimizer_->step();
      for (size_t i = 0; i < critics_.size(); ++i) polyak(*targets_[i], *critics_[i], tau_);
      polyak(*actor_target_, *actor_, tau_);
    }
    return critic_loss.item<double>();
  }

  Eigen::VectorXf actor() const { return flat_parameters({actor_.get()}); }
  Eigen::VectorXf actor_target() const { return flat_parameters({actor_target_.get()}); }
  Eigen::VectorXf critics() const { return flat(critics_); }
  Eigen::VectorXf targets() const { return flat(targets_); }

 private:
  static Eigen::VectorXf flat(const std::vector<torch::nn::Sequential>& modules) {
    std::vector<const torch::nn::Module*> pointers;
    for (const auto& module : modules) pointers.push_back(module.get());
    return flat_parameters(pointers);
  }

  Settings settings_;
  double gamma_, tau_;
  torch::nn::Sequential actor_, actor_target_;
  std::vector<torch::nn::Sequential> critics_, targets_;
  std::unique_ptr<torch::optim::Adam> actor_optimizer_, critic_optimizer_;
};

class Td3Update : public ScratchDirectoryTest, public ::testing::WithParamInterface<Settings> {
 protected:
  Td3Update() : ScratchDirectoryTest("td3_update") {}
};

TEST_P(Td3Update, MatchesStableBaselines3UpdateWrittenWithAutograd) {
  const Settings& settings = GetParam();
  const double gamma = 0.98, tau = 0.1;
  std::string algo =
      "buffer_size: " + std::to_string(kBufferSize) + "\nbatch_size: " + std::to_string(kBatch) +
      "\nnet_arch: [16, 16]\ngamma: 0.98\ntau: 0.1\nlearning_rate: " +
      std::to_string(settings.learning_rate) +
      "\ncritic_learning_rate: " + std::to_string(settings.critic_learning_rate) + "\n";
  if (!settings.ddpg) {
    algo += "policy_delay: " + std::to_string(settings.policy_delay) +
            "\ntarget_policy_noise: " + std::to_string(settings.target_noise) +
            "\ntarget_noise_clip: " + std::to_string(settings.noise_clip) + "\n";
  }
  const Td3Config config = Td3Config::from_config(
      Config::parse(algo), settings.ddpg ? Td3Variant::kDdpg : Td3Variant::kTd3);
  ASSERT_EQ(config.n_critics, settings.critics);
  ASSERT_EQ(config.policy_delay, settings.policy_delay);
  ASSERT_EQ(config.target_policy_noise, settings.target_noise);
  envs::ThreadedVecEnv env(1, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
  Td3UnderTest agent(env, config, 4, settings.ddpg ? Td3Variant::kDdpg : Td3Variant::kTd3);
  testing::write_random_replay_buffer(directory_ / "buffer.bin", kBufferSize, kObservations,
                                      kActions, 22);
  agent.load_replay_buffer(directory_ / "buffer.bin");

  const int64_t actor_count =
      parameter_count(*reference_mlp({kObservations, kHidden, kHidden, kActions}, false));
  const int64_t critic_count =
      settings.critics *
      parameter_count(*reference_mlp({kObservations + kActions, kHidden, kHidden, 1}, false));
  agent.save(directory_ / "before.ckpt");
  Parameters start = read_parameters(directory_ / "before.ckpt", actor_count, critic_count);

  ReferenceTd3 reference(start, settings, gamma, tau);
  double critic_loss = 0.0, actor_loss = 0.0;
  int actor_steps = 0;
  ReplayBuffer::Batch batch;
  for (int step = 0; step < kGradientSteps; ++step) {
    agent.replay_buffer().sample(kBatch, start.samples, batch);
    const torch::Tensor noise = settings.target_noise > 0
                                    ? standard_normal(start.samples, kBatch, kActions)
                                    : torch::zeros({kBatch, kActions});
    std::optional<double> step_actor_loss;
    critic_loss +=
        reference.step(batch, noise, agent.gradient_updates() + step + 1, step_actor_loss) /
        kGradientSteps;
    if (step_actor_loss) {
      actor_loss += *step_actor_loss;
      ++actor_steps;
    }
  }
  ASSERT_EQ(actor_steps, kGradientSteps / settings.policy_delay);
  const TrainStats stats = agent.update(kGradientSteps, 1.0);
  agent.save(directory_ / "after.ckpt");
  const Parameters end = read_parameters(directory_ / "after.ckpt", actor_count, critic_count);

  EXPECT_NEAR(stat(stats, "train/critic_loss"), critic_loss, 1e-5 * critic_loss);
  actor_loss /= actor_steps;
  EXPECT_NEAR(stat(stats, "train/actor_loss"), actor_loss, 1e-5 * std::abs(actor_loss) + 1e-7);

  const double actor_step = settings.learning_rate, critic_step = settings.critic_learning_rate;
  EXPECT_GT(max_difference(end.actor, start.actor), 0.5 * actor_step);
  EXPECT_LT(max_difference(end.actor, reference.actor()), 1e-3 * actor_step);
  EXPECT_GT(max_difference(end.critics, start.critics), 0.5 * critic_step);
  EXPECT_LT(max_difference(end.critics, reference.critics()), 1e-3 * critic_step);
  EXPECT_GT(max_difference(end.actor_target, start.actor_target), 0.1 * tau * actor_step);
  EXPECT_LT(max_difference(end.actor_target, reference.actor_target()),
            1e-3 * tau * actor_step + float_rounding(end.actor_target));
  EXPECT_LT(max_difference(end.critics_target, reference.targets()),
            1e-3 * tau * critic_step + float_rounding(end.critics_target));
}

INSTANTIATE_TEST_SUITE_P(
    Algorithms, Td3Update,
    ::testing::Values(Settings{"Td3", false, 2, 2, 0.2, 0.5, 2e-3, 2e-3},
                      // Smoothing noise wide enough that the clip at ±c and at ±1 both bind.
                      Settings{"Td3WideSmoothing", false, 2, 1, 0.6, 0.3, 1e-3, 3e-3},
                      Settings{"Ddpg", true, 1, 1, 0.0, 0.5, 1e-3, 3e-3}),
    [](const ::testing::TestParamInfo<Settings>& info) { return info.param.name; });

}  // namespace
}  // namespace tendril::rl
