// SAC with a trainable policy head (seed 001, thesis §5.1.2, Fig. 5.2) against an independent
// LibTorch-autograd implementation of the same update: the head (an MLP on the last values of the
// observation) and torch.nn.LayerNorm feed actor and critics beside the observation's first
// values; the critic loss and then the actor loss are back-propagated into the head, which takes
// one Adam step on their summed gradient after the critics' and the actor's steps; its target
// copy is Polyak-averaged with the critics'. After a few gradient steps every parameter — head,
// target head, actor, critics, target critics — must agree to float rounding. A frozen head must
// not move at all.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "envs/scripted_env.hpp"
#include "support/error_message.hpp"
#include "support/random_replay_buffer.hpp"
#include "support/reference_networks.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/rl/sac/sac.hpp"

namespace tendril::rl {
namespace {

using namespace tendril::testing;

constexpr int64_t kObservations = 3;  // ScriptedEnv's: [direct | history of 2 values]
constexpr int64_t kDirect = 1;
constexpr int64_t kHistory = 2;
constexpr int64_t kFeatures = 4;  // the head's output
constexpr int64_t kActions = 2;
constexpr int64_t kHidden = 16;
constexpr int64_t kBatch = 64;
constexpr int64_t kBufferSize = 400;
constexpr int kGradientSteps = 3;

class SacUnderTest : public Sac {
 public:
  using Sac::Sac;
  TrainStats update(int64_t steps, double progress_remaining) {
    return train(steps, progress_remaining);
  }
};

struct Parameters {
  Eigen::VectorXf head, head_target, actor, critics, critics_target;
  Rng samples;
};

Parameters read_parameters(const std::filesystem::path& file) {
  const ArchiveReader reader(file, "checkpoint");
  return {reader.get_floats("head_parameters"),  reader.get_floats("head_target"),
          reader.get_floats("actor_parameters"), reader.get_floats("critics_parameters"),
          reader.get_floats("critics_target"),   reader.get_rng("rng_updates")};
}

// The update written with torch modules and autograd, with α fixed.
class ReferenceHeadedSac {
 public:
  ReferenceHeadedSac(const Parameters& start, double learning_rate, double gamma, double tau,
                     double alpha)
      : head_(reference_mlp({kHistory, 8, kFeatures}, false)),
        target_head_(reference_mlp({kHistory, 8, kFeatures}, false)),
        actor_(reference_mlp({kFeatures + kDirect, kHidden, kHidden, 2 * kActions}, false)),
        gamma_(gamma),
        tau_(tau),
        alpha_(alpha) {
    const std::vector<int64_t> critic_sizes{kFeatures + kDirect + kActions, kHidden, kHidden, 1};
    for (int i = 0; i < 2; ++i) {
      critics_.push_back(reference_mlp(critic_sizes, false));
      targets_.push_back(reference_mlp(critic_sizes, false));
    }
    EXPECT_EQ(load_flat(*head_, start.head), start.head.size());
    EXPECT_EQ(load_flat(*target_head_, start.head_target), start.head_target.size());
    EXPECT_EQ(load_flat(*actor_, start.actor), start.actor.size());
    int64_t offset = 0, target_offset = 0;
    for (int i = 0; i < 2; ++i) {
      offset = load_flat(*critics_[i], start.critics, offset);
      target_offset = load_flat(*targets_[i], start.critics_target, target_offset);
    }
    const auto options = torch::optim::AdamOptions(learning_rate);
    head_optimizer_ = std::make_unique<torch::optim::Adam>(head_->parameters(), options);
    actor_optimizer_ = std::make_unique<torch::optim::Adam>(actor_->parameters(), options);
    std::vector<torch::Tensor> critic_parameters;
    for (auto& critic : critics_) {
      for (auto& p : critic->parameters()) critic_parameters.push_back(p);
    }
    critic_optimizer_ = std::make_unique<torch::optim::Adam>(critic_parameters, options);
  }

  void step(const ReplayBuffer::Batch& batch, const torch::Tensor& noise,
            const torch::Tensor& next_noise) {
    const torch::Tensor observations = rows_of(batch.observations);
    const torch::Tensor next_observations = rows_of(batch.next_observations);
    const torch::Tensor actions = rows_of(batch.actions);
    const torch::Tensor rewards = column_tensor(batch.rewards);
    const torch::Tensor dones = column_tensor(batch.terminated);

    head_optimizer_->zero_grad();
    const torch::Tensor encoded = encode(head_, observations);
    auto [actions_pi, log_prob] = squashed_gaussian_sample(actor_, encoded, noise, kActions);
    torch::Tensor target_q;
    {
      torch::NoGradGuard no_grad;
      auto [next_actions, next_log_prob] =
          squashed_gaussian_sample(actor_, encode(head_, next_observations), next_noise, kActions);
      const torch::Tensor next_inputs =
          torch::cat({encode(target_head_, next_observations), next_actions}, 1);
      torch::Tensor next_q =
          torch::cat({targets_[0]->forward(next_inputs), targets_[1]->forward(next_inputs)}, 1);
      next_q = std::get<0>(torch::min(next_q, 1, /*keepdim=*/true)) - alpha_ * next_log_prob;
      target_q = rewards + (1 - dones) * gamma_ * next_q;
    }
    const torch::Tensor inputs = torch::cat({encoded, actions}, 1);
    torch::Tensor critic_loss = torch::zeros({});
    for (auto& critic : critics_) {
      critic_loss = critic_loss + torch::mse_loss(critic->forward(inputs), target_q);
    }
    critic_loss = 0.5 * critic_loss;
    critic_optimizer_->zero_grad();
    critic_loss.backward({}, /*retain_graph=*/true);
    critic_optimizer_->step();

    const torch::Tensor pi_inputs = torch::cat({encoded, actions_pi}, 1);
    const torch::Tensor q_pi =
        torch::cat({critics_[0]->forward(pi_inputs), critics_[1]->forward(pi_inputs)}, 1);
    const torch::Tensor actor_loss =
        (alpha_ * log_prob - std::get<0>(torch::min(q_pi, 1, /*keepdim=*/true))).mean();
    actor_optimizer_->zero_grad();
    actor_loss.backward();
    actor_optimizer_->step();
    head_optimizer_->step();

    torch::NoGradGuard no_grad;
    polyak(*critics_[0], *targets_[0]);
    polyak(*critics_[1], *targets_[1]);
    polyak(*head_, *target_head_);
  }

  Eigen::VectorXf head() const { return flat_parameters({head_.get()}); }
  Eigen::VectorXf head_target() const { return flat_parameters({target_head_.get()}); }
  Eigen::VectorXf actor() const { return flat_parameters({actor_.get()}); }
  Eigen::VectorXf critics() const {
    return flat_parameters({critics_[0].get(), critics_[1].get()});
  }
  Eigen::VectorXf targets() const {
    return flat_parameters({targets_[0].get(), targets_[1].get()});
  }

 private:
  // [LayerNorm(head(history)), direct]
  static torch::Tensor encode(torch::nn::Sequential& head, const torch::Tensor& observations) {
    const torch::Tensor features = torch::layer_norm(
        head->forward(observations.slice(1, kDirect, kObservations)), {kFeatures}, {}, {}, 1e-5);
    return torch::cat({features, observations.slice(1, 0, kDirect)}, 1);
  }

  void polyak(torch::nn::Module& online, torch::nn::Module& target) const {
    const auto from = online.parameters();
    auto to = target.parameters();
    for (size_t k = 0; k < from.size(); ++k) to[k].mul_(1 - tau_).add_(from[k], tau_);
  }

  torch::nn::Sequential head_, target_head_, actor_;
  std::vector<torch::nn::Sequential> critics_, targets_;
  std::unique_ptr<torch::optim::Adam> head_optimizer_, actor_optimizer_, critic_optimizer_;
  double gamma_, tau_, alpha_;
};

class SacHeadUpdate : public ScratchDirectoryTest {
 protected:
  SacHeadUpdate() : ScratchDirectoryTest("sac_head_update") {}

  SacConfig config(bool trainable) const {
    return SacConfig::from_config(Config::parse(
        "buffer_size: " + std::to_string(kBufferSize) + "\nbatch_size: " + std::to_string(kBatch) +
        "\nnet_arch: [16, 16]\nlearning_rate: 3e-3\ngamma: 0.98\ntau: 0.1\nent_coef: 0.2\n"
        "head: {kind: mlp, inputs: 2, layers: [8, 4], trainable: " +
        (trainable ? "true" : "false") + "}\n"));
  }
};

TEST_F(SacHeadUpdate, TrainableHeadMatchesTheUpdateWrittenWithAutograd) {
  const double learning_rate = 3e-3, gamma = 0.98, tau = 0.1;
  envs::ThreadedVecEnv env(1, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
  SacUnderTest agent(env, config(true), 5);
  // A trainable head runs in every update, so the buffer keeps observations.
  write_random_replay_buffer(directory_ / "buffer.bin", kBufferSize, kObservations, kActions, 21);
  agent.load_replay_buffer(directory_ / "buffer.bin");
  agent.save(directory_ / "before.ckpt");
  Parameters start = read_parameters(directory_ / "before.ckpt");
  ASSERT_EQ(start.head.size(), (kHistory + 1) * 8 + (8 + 1) * kFeatures);
  ASSERT_TRUE(start.head == start.head_target);

  ReferenceHeadedSac reference(start, learning_rate, gamma, tau, 0.2);
  ReplayBuffer::Batch batch;
  for (int step = 0; step < kGradientSteps; ++step) {
    agent.replay_buffer().sample(kBatch, start.samples, batch);
    const torch::Tensor noise = standard_normal(start.samples, kBatch, kActions);
    const torch::Tensor next_noise = standard_normal(start.samples, kBatch, kActions);
    reference.step(batch, noise, next_noise);
  }
  agent.update(kGradientSteps, 1.0);
  agent.save(directory_ / "after.ckpt");
  const Parameters end = read_parameters(directory_ / "after.ckpt");

  const double step_size = learning_rate;
  EXPECT_GT(max_difference(end.head, start.head), 0.5 * step_size);
  EXPECT_LT(max_difference(end.head, reference.head()), 1e-3 * step_size);
  EXPECT_GT(max_difference(end.head_target, start.head_target), 0.1 * tau * step_size);
  EXPECT_LT(max_difference(end.head_target, reference.head_target()),
            1e-3 * tau * step_size + float_rounding(end.head_target));
  EXPECT_LT(max_difference(end.actor, reference.actor()), 1e-3 * step_size);
  EXPECT_LT(max_difference(end.critics, reference.critics()), 1e-3 * step_size);
  EXPECT_LT(max_difference(end.critics_target, reference.targets()),
            1e-3 * tau * step_size + float_rounding(end.critics_target));
}

TEST_F(SacHeadUpdate, FrozenHeadNeverChangesAndTheBufferKeepsItsFeatures) {
  envs::ThreadedVecEnv env(2, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
  SacConfig frozen = config(false);
  frozen.common.learning_starts = 20;
  Sac agent(env, frozen, 5);
  const Eigen::VectorXf head = agent.head_parameters();
  const Eigen::VectorXf actor =
      dynamic_cast<const SquashedGaussianPolicy&>(agent.policy()).parameters();
  agent.learn(200);
  EXPECT_TRUE(agent.head_parameters() == head);
  EXPECT_TRUE(agent.head_target_parameters() == head);
  EXPECT_FALSE(dynamic_cast<const SquashedGaussianPolicy&>(agent.policy()).parameters() == actor);
  // The buffer holds [LayerNorm(head(history)), direct] of what the envs observed: transition k
  // is env k % 2's step k / 2 of its only episode, observation [k / 2, resets, seed] (ScriptedEnv
  // never ends an episode; one more step shows each env's resets and seed).
  const ReplayBuffer& buffer = agent.replay_buffer();
  ASSERT_EQ(buffer.observation_size(), kFeatures + kDirect);
  const auto& policy = dynamic_cast<const SquashedGaussianPolicy&>(agent.policy());
  Eigen::MatrixXf observed(kObservations, 20);
  for (int env_index = 0; env_index < 2; ++env_index) {
    const Observation now = env.env(env_index).step(Eigen::Vector2f::Zero()).observation;
    for (int k = env_index; k < 20; k += 2)
      observed.col(k) << static_cast<float>(k / 2), now[1], now[2];
  }
  ObservationEncoder::Pass pass;
  policy.encoder().encode(head, observed, false, pass);
  for (int k = 0; k < 20; ++k) {
    const Eigen::VectorXf stored = buffer.observation(k);
    EXPECT_TRUE(stored.isApprox(pass.encoded.col(k), 1e-5f))
        << "transition " << k << ": " << stored.transpose() << " vs "
        << pass.encoded.col(k).transpose();
  }
}

TEST_F(SacHeadUpdate, CheckpointRoundTripResumesExactly) {
  auto run = [&](bool interrupted) {
    envs::ThreadedVecEnv env(2, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
    SacConfig trainable = config(true);
    trainable.common.learning_starts = 20;
    auto agent = std::make_unique<Sac>(env, trainable, 9);
    agent->learn(100);
    if (interrupted) {
      agent->save(directory_ / "middle.ckpt");
      agent->save_replay_buffer(directory_ / "middle.buffer");
      agent = std::make_unique<Sac>(env, trainable, 1234);  // other weights until loaded
      agent->load(directory_ / "middle.ckpt");
      agent->load_replay_buffer(directory_ / "middle.buffer");
    }
    agent->learn(200);
    agent->save_policy(directory_ / (interrupted ? "resumed.policy" : "straight.policy"));
    return std::make_pair(agent->head_parameters(), agent->head_target_parameters());
  };
  const auto straight = run(false);
  const auto resumed = run(true);
  EXPECT_TRUE(straight.first == resumed.first);
  EXPECT_TRUE(straight.second == resumed.second);
  // The policy file carries the head: loaded, it acts as the trained policy.
  const auto policy = load_policy(directory_ / "resumed.policy");
  const auto& loaded = dynamic_cast<const SquashedGaussianPolicy&>(*policy);
  ASSERT_TRUE(loaded.encoder().has_head());
  EXPECT_TRUE(loaded.head_parameters() == resumed.first);
  Rng a(3), b(3);
  envs::BatchMatrix observations = envs::BatchMatrix::Random(5, 3), first, second;
  policy->act(observations, true, a, first);
  load_policy(directory_ / "straight.policy")->act(observations, true, b, second);
  EXPECT_TRUE(first == second);
}

TEST_F(SacHeadUpdate, HeadReadingMoreThanTheObservationIsRefused) {
  envs::ThreadedVecEnv env(1, [](int) { return std::make_unique<envs::testing::ScriptedEnv>(); });
  SacConfig wide = config(false);
  wide.head->inputs = 4;
  const std::string message = error_message([&] { Sac agent(env, wide, 1); });
  EXPECT_NE(message.find("reads 4 values"), std::string::npos) << message;
}

}  // namespace
}  // namespace tendril::rl
