// SAC, TD3, DDPG and DQN: SB3's identity checks, reproducibility, save/load with and without the
// replay buffer, timeouts in the buffer, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "support/error_message.hpp"
#include "support/evaluation.hpp"
#include "support/learning_seed.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/dqn/dqn.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/td3/td3.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<envs::VecEnv> vec_env(const std::string& id, const std::string& params,
                                      int n_envs = 1) {
  VecEnvOptions options;
  options.id = id;
  options.params = Config::parse(params);
  options.n_envs = n_envs;
  return make_vec_env(options);
}

std::unique_ptr<OffPolicyAlgorithm> make(const std::string& algorithm, envs::VecEnv& env,
                                         const std::string& algo, uint64_t seed) {
  const Config config = Config::parse(algo);
  if (algorithm == "sac" || algorithm == "sac_sde") {
    return std::make_unique<Sac>(env, SacConfig::from_config(config), seed);
  }
  if (algorithm == "td3") {
    return std::make_unique<Td3>(env, Td3Config::from_config(config, Td3Variant::kTd3), seed);
  }
  if (algorithm == "ddpg") {
    return std::make_unique<Td3>(env, Td3Config::from_config(config, Td3Variant::kDdpg), seed,
                                 Td3Variant::kDdpg);
  }
  return std::make_unique<Dqn>(env, DqnConfig::from_config(config), seed);
}

fs::path temporary(const std::string& name) {
  return fs::temp_directory_path() /
         ("tendril_off_policy_" + name + "_" + std::to_string(::getpid()));
}

// Stable-Baselines3's identity checks (tests/test_identity.py): ≥ 90 of 100 per episode over 20
// deterministic episodes after a few thousand steps; γ small since actions do not affect the
// future.
double identity_score(const std::string& algorithm, const std::string& id, const std::string& algo,
                      int64_t budget) {
  const std::string params = id == "Identity-v0" ? "n: 10" : "eps: 0.5";
  auto env = vec_env(id, params);
  const uint64_t seed = testing::learning_seed(0);
  auto agent = make(algorithm, *env, algo, seed);
  agent->learn(budget);
  auto evaluation_env = envs::make(id, Config::parse(params));
  const double score =
      testing::evaluate(agent->policy(), *evaluation_env, 20, seed + 1000).mean_return();
  std::printf("%s on %s: return %.1f\n", algorithm.c_str(), id.c_str(), score);
  return score;
}

constexpr const char* kSmallBox = "gamma: 0.5\nlearning_starts: 100\nnet_arch: [64, 64]\n";

TEST(OffPolicyIdentity, SacSolvesBoxIdentity) {
  EXPECT_GE(identity_score("sac", "IdentityBox-v0", kSmallBox, 2000), 90.0);
}

TEST(OffPolicyIdentity, SacWithStateDependentExplorationSolvesBoxIdentity) {
  EXPECT_GE(
      identity_score("sac", "IdentityBox-v0", std::string(kSmallBox) + "use_sde: true\n", 2000),
      90.0);
}

TEST(OffPolicyIdentity, Td3SolvesBoxIdentity) {
  EXPECT_GE(identity_score("td3", "IdentityBox-v0",
                           std::string(kSmallBox) + "noise_type: normal\nnoise_std: 0.1\n", 2000),
            90.0);
}

TEST(OffPolicyIdentity, DdpgSolvesBoxIdentity) {
  EXPECT_GE(identity_score("ddpg", "IdentityBox-v0",
                           std::string(kSmallBox) + "noise_type: normal\nnoise_std: 0.1\n", 2000),
            90.0);
}

TEST(OffPolicyIdentity, DqnSolvesDiscreteIdentity) {
  EXPECT_GE(identity_score("dqn", "Identity-v0",
                           "gamma: 0.5\nlearning_starts: 100\nlearning_rate: 1e-3\n"
                           "target_update_interval: 100\nexploration_fraction: 0.3\n"
                           "train_freq: 1\n",
                           5000),
            90.0);
}

// The bounded head Q = B·tanh(z): Identity's values (≤ 1/(1 − γ) = 2) lie inside B = 4.
TEST(OffPolicyIdentity, DqnWithABoundedHeadSolvesDiscreteIdentity) {
  EXPECT_GE(identity_score("dqn", "Identity-v0",
                           "gamma: 0.5\nlearning_starts: 100\nlearning_rate: 1e-3\n"
                           "target_update_interval: 100\nexploration_fraction: 0.3\n"
                           "train_freq: 1\nq_bound: 4\n",
                           5000),
            90.0);
}

// Deterministic actions of an agent on fixed observations.
envs::BatchMatrix probe(OffPolicyAlgorithm& agent, int observation_size) {
  envs::BatchMatrix observations(5, observation_size);
  for (int i = 0; i < observations.size(); ++i) {
    observations.data()[i] = std::sin(0.7f * static_cast<float>(i));
  }
  return agent.predict(observations, /*deterministic=*/true);
}

class EveryAlgorithm : public ::testing::TestWithParam<std::string> {
 protected:
  std::string id() const { return GetParam() == "dqn" ? "CartPole-v1" : "Pendulum-v1"; }
  std::string algo() const {
    const std::string common =
        "learning_starts: 200\nbatch_size: 32\nnet_arch: [32, 32]\nlog_interval: 300\n";
    if (GetParam() == "dqn") return common + "target_update_interval: 50\n";
    if (GetParam() == "sac") return common;
    if (GetParam() == "sac_sde") return common + "use_sde: true\nsde_sample_freq: 4\n";
    return common + "noise_type: ornstein_uhlenbeck\n";  // per-env noise state in checkpoints
  }
  std::unique_ptr<OffPolicyAlgorithm> agent(envs::VecEnv& env, uint64_t seed) const {
    return make(GetParam(), env, algo(), seed);
  }
};

TEST_P(EveryAlgorithm, SameSeedSameRunOtherSeedOtherRun) {
  auto env_a = vec_env(id(), "", 2), env_b = vec_env(id(), "", 2), env_c = vec_env(id(), "", 2);
  auto a = agent(*env_a, 7), b = agent(*env_b, 7), c = agent(*env_c, 8);
  std::vector<double> returns_a, returns_b, returns_c;
  const auto record = [](std::vector<double>& returns) {
    return [&returns](const Progress& p) {
      returns.push_back(p.episode_return_mean);
      return true;
    };
  };
  a->learn(1200, record(returns_a));
  b->learn(1200, record(returns_b));
  c->learn(1200, record(returns_c));
  EXPECT_EQ(returns_a, returns_b);
  EXPECT_NE(returns_a, returns_c);
  const int size = env_a->observation_space().size();
  EXPECT_EQ(probe(*a, size), probe(*b, size));
  EXPECT_GT(a->gradient_updates(), 0);
}

TEST_P(EveryAlgorithm, SaveLoadWithBufferContinuesExactly) {
  auto env = vec_env(id(), "", 2);
  auto original = agent(*env, 3);
  original->learn(900);
  const fs::path model = temporary("model_" + GetParam()),
                 buffer = temporary("buffer_" + GetParam());
  original->save(model);
  original->save_replay_buffer(buffer);

  auto other_env = vec_env(id(), "", 2);
  auto restored = agent(*other_env, 99);  // a different seed: everything must come from the files
  restored->load(model);
  restored->load_replay_buffer(buffer);
  const int size = env->observation_space().size();
  EXPECT_EQ(probe(*restored, size), probe(*original, size));
  EXPECT_EQ(restored->num_timesteps(), original->num_timesteps());

  // The checkpoint holds the environments too: both go on from the same episodes identically.
  original->learn(1800);
  restored->learn(1800);
  EXPECT_EQ(probe(*restored, size), probe(*original, size));
  fs::remove(model);
  fs::remove(buffer);
}

TEST_P(EveryAlgorithm, SaveLoadWithoutBufferKeepsThePolicy) {
  auto env = vec_env(id(), "", 1);
  auto original = agent(*env, 4);
  original->learn(600);
  const fs::path model = temporary("model_nobuffer_" + GetParam());
  original->save(model);
  auto other_env = vec_env(id(), "", 1);
  auto restored = agent(*other_env, 5);
  restored->load(model);
  const int size = env->observation_space().size();
  EXPECT_EQ(probe(*restored, size), probe(*original, size));
  EXPECT_EQ(restored->replay_buffer().size(), 0);
  restored->learn(1200);  // learns on from an empty buffer
  EXPECT_GT(restored->replay_buffer().size(), 0);
  fs::remove(model);
}

TEST_P(EveryAlgorithm, CorruptCheckpointChangesNothing) {
  auto env = vec_env(id(), "", 1);
  auto agent_a = agent(*env, 6);
  agent_a->learn(400);
  const fs::path model = temporary("corrupt_" + GetParam());
  agent_a->save(model);
  std::string bytes;
  {
    std::ifstream in(model, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::ofstream(model, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  auto other_env = vec_env(id(), "", 1);
  auto agent_b = agent(*other_env, 7);
  const envs::BatchMatrix before = probe(*agent_b, env->observation_space().size());
  EXPECT_THROW(agent_b->load(model), Error);
  EXPECT_EQ(probe(*agent_b, env->observation_space().size()), before);
  fs::remove(model);
}

INSTANTIATE_TEST_SUITE_P(OffPolicy, EveryAlgorithm,
                         ::testing::Values("sac", "sac_sde", "td3", "ddpg", "dqn"));

TEST(OffPolicyThreads, TwoLearnerThreadsRepeatTheRunExactly) {
  // Networks and batch large enough that OpenBLAS splits the products between the threads.
  const std::string algo =
      "learning_starts: 100\nbatch_size: 128\nnet_arch: [256, 256]\nlog_interval: 100\n"
      "learner_threads: 2\n";
  std::vector<envs::BatchMatrix> actions;
  for (int run = 0; run < 2; ++run) {
    auto env = vec_env("Pendulum-v1", "");
    auto sac = make("sac", *env, algo, 11);
    sac->learn(300);
    actions.push_back(probe(*sac, env->observation_space().size()));
  }
  EXPECT_EQ(actions[0], actions[1]);
}

// One Pendulum-v1 step (Gymnasium's dynamics: g = 10, m = l = 1, dt = 0.05, semi-implicit Euler,
// speed clipped to ±8) from an observation (cos θ, sin θ, θ̇) under a torque.
Eigen::Vector3d pendulum_step(const Eigen::Vector3f& observation, double torque) {
  const double theta = std::atan2(observation[1], observation[0]);
  const double theta_dot =
      std::clamp(observation[2] + (15.0 * std::sin(theta) + 3.0 * torque) * 0.05, -8.0, 8.0);
  const double next = theta + theta_dot * 0.05;
  return {std::cos(next), std::sin(next), theta_dot};
}

TEST(OffPolicyBuffer, TruncatedEpisodesAreStoredAsNotTerminatedWithTheirFinalObservation) {
  auto env = vec_env("Pendulum-v1", "max_episode_steps: 50");
  Sac sac(*env, SacConfig::from_config(Config::parse("learning_starts: 1000\n")), 0);
  sac.learn(120);  // warm-up only: random actions, 2 episodes cut by the time limit
  const ReplayBuffer& buffer = sac.replay_buffer();
  ASSERT_EQ(buffer.size(), 120);
  for (int64_t i = 0; i < buffer.size(); ++i) {
    EXPECT_FALSE(buffer.terminated(i)) << i;
    // Every next observation is one Pendulum step from its observation under its action (in
    // [−1, 1], so 2 N·m per unit), at the cuts too: there it is the episode's final state.
    const Eigen::Vector3d expected =
        pendulum_step(buffer.observation(i), 2.0 * buffer.action(i)[0]);
    EXPECT_LT((buffer.next_observation(i).cast<double>() - expected).cwiseAbs().maxCoeff(), 1e-5)
        << "transition " << i;
    // Within an episode, next observation i is observation i + 1; at the cuts (49, 99) the
    // next episode starts from a fresh reset instead.
    if (i + 1 < buffer.size()) {
      if (i == 49 || i == 99) {
        EXPECT_NE(buffer.next_observation(i), buffer.observation(i + 1)) << i;
      } else {
        EXPECT_EQ(buffer.next_observation(i), buffer.observation(i + 1)) << i;
      }
    }
  }
}

// CartPole ends when |x| > 2.4 m or |θ| > 12°: the terminated flag must sit exactly on the
// transitions whose next observation is out of those bounds, after which a new episode starts.
TEST(OffPolicyBuffer, TerminationsAreStoredAsTerminated) {
  auto env = vec_env("CartPole-v1", "");
  Dqn dqn(*env, DqnConfig::from_config(Config::parse("learning_starts: 1000\n")), 0);
  dqn.learn(300);
  const ReplayBuffer& buffer = dqn.replay_buffer();
  ASSERT_EQ(buffer.size(), 300);
  int terminated = 0;
  const double max_angle = 12.0 * 2.0 * std::numbers::pi / 360.0;
  for (int64_t i = 0; i < buffer.size(); ++i) {
    const auto next = buffer.next_observation(i);
    const bool outside = std::abs(next[0]) > 2.4f || std::abs(next[2]) > max_angle;
    EXPECT_EQ(buffer.terminated(i), outside) << "transition " << i;
    if (i + 1 < buffer.size()) {
      EXPECT_EQ(buffer.terminated(i), next != buffer.observation(i + 1)) << "transition " << i;
    }
    terminated += buffer.terminated(i);
  }
  EXPECT_GT(terminated, 3);  // random CartPole episodes fall within ~20 steps
}

// A Box action space with an infinite bound.
class UnboundedEnv : public Env {
 public:
  const Space& observation_space() const override { return observations_; }
  const Space& action_space() const override { return actions_; }
  Observation reset(std::optional<uint64_t>) override { return Observation::Zero(2); }
  Step step(const Action&) override { return {Observation::Zero(2), 0.0, false, false, {}}; }

 private:
  Space observations_ = Space::box(2, -1.0f, 1.0f);
  Space actions_ = Space::box(Eigen::Vector2f(-1.0f, -1.0f),
                              Eigen::Vector2f(1.0f, std::numeric_limits<float>::infinity()));
};

TEST(OffPolicyBadInput, UnboundedActionSpaceIsRefused) {
  envs::ThreadedVecEnv env(1, [](int) { return std::make_unique<UnboundedEnv>(); });
  for (const std::string algorithm : {"sac", "td3", "ddpg"}) {
    const std::string message = testing::error_message([&] { make(algorithm, env, "{}", 0); });
    EXPECT_NE(message.find("finite action bounds"), std::string::npos) << message;
  }
}

TEST(OffPolicyBadInput, WrongSpacesAndSizesAreNamed) {
  auto box = vec_env("Pendulum-v1", "");
  auto discrete = vec_env("CartPole-v1", "");
  EXPECT_NE(testing::error_message([&] { make("dqn", *box, "{}", 0); }).find("Discrete"),
            std::string::npos);
  EXPECT_NE(testing::error_message([&] { make("sac", *discrete, "{}", 0); }).find("Box"),
            std::string::npos);
  auto sac = make("sac", *box, "{}", 0);
  const Observation wrong_size = Observation::Zero(5);
  EXPECT_NE(testing::error_message([&] {
              sac->predict(wrong_size, true);
            }).find("5 components, the policy expects 3"),
            std::string::npos);
  Observation nan = Observation::Zero(3);
  nan[1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(testing::error_message([&] { sac->predict(nan, true); }).find("not finite"),
            std::string::npos);
  // A checkpoint of another action size.
  auto mountain_car = vec_env("MountainCarContinuous-v0", "");
  auto other = make("sac", *mountain_car, "{}", 0);
  const fs::path model = temporary("other_size");
  other->save(model);
  EXPECT_NE(testing::error_message([&] { sac->load(model); }).find("observations are Box(2"),
            std::string::npos);
  fs::remove(model);
}

TEST(OffPolicyBadInput, ConfigErrorsNameTheKey) {
  EXPECT_NE(
      testing::error_message([] { SacConfig::from_config(Config::parse("tau: 2")); }).find("tau"),
      std::string::npos);
  EXPECT_NE(testing::error_message([] {
              SacConfig::from_config(Config::parse("preset: sb9"));
            }).find("sb3, sb2"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              SacConfig::from_config(Config::parse("ent_coef: autox"));
            }).find("ent_coef"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              Td3Config::from_config(Config::parse("noise_type: pink"), Td3Variant::kTd3);
            }).find("noise_type"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              DqnConfig::from_config(Config::parse("polyak: 1"));
            }).find("polyak"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              DqnConfig::from_config(Config::parse("q_bound: -100"));
            }).find("q_bound"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              SacConfig::from_config(Config::parse("learner_threads: 0"));
            }).find("learner_threads"),
            std::string::npos);
  // DDPG has no TD3-only keys.
  EXPECT_NE(testing::error_message([] {
              Td3Config::from_config(Config::parse("policy_delay: 2"), Td3Variant::kDdpg);
            }).find("policy_delay"),
            std::string::npos);
}

TEST(OffPolicyPresets, Sb2PresetsCarryStableBaselinesV2Defaults) {
  const SacConfig sac = SacConfig::from_config(Config::parse("preset: sb2"));
  EXPECT_EQ(sac.common.buffer_size, 50000);
  EXPECT_EQ(sac.common.batch_size, 64);
  EXPECT_EQ(sac.common.net_arch, (std::vector<int64_t>{64, 64}));
  const Td3Config td3 = Td3Config::from_config(Config::parse("preset: sb2"), Td3Variant::kTd3);
  EXPECT_EQ(td3.common.train_freq, 100);
  EXPECT_EQ(td3.common.gradient_steps, 100);
  EXPECT_EQ(td3.common.batch_size, 128);
  const Td3Config ddpg = Td3Config::from_config(Config::parse("preset: sb2"), Td3Variant::kDdpg);
  EXPECT_EQ(ddpg.n_critics, 1);
  EXPECT_EQ(ddpg.common.tau, 0.001);
  EXPECT_EQ(*ddpg.critic_learning_rate, 1e-3);
  EXPECT_EQ(ddpg.common.learning_rate.initial, 1e-4);
  const Td3Config sb3_ddpg = Td3Config::from_config(Config::parse("{}"), Td3Variant::kDdpg);
  EXPECT_EQ(sb3_ddpg.policy_delay, 1);
  EXPECT_EQ(sb3_ddpg.target_policy_noise, 0.0);
  EXPECT_EQ(sb3_ddpg.common.net_arch, (std::vector<int64_t>{400, 300}));
}

}  // namespace
}  // namespace tendril::rl
