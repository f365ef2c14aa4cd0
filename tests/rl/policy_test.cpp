// Policies apart from their algorithms: model files round trip for every kind, carry the
// observation normalization, and are refused when damaged.
#include "tendril/rl/policy.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/envs/vector/vec_normalize.hpp"
#include "tendril/rl/algorithm_registry.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

class PolicyFile : public testing::ScratchDirectoryTest {
 protected:
  PolicyFile() : ScratchDirectoryTest("policy_test") {}
};

envs::BatchMatrix observations_of(const Space& space, int count, Rng& rng) {
  envs::BatchMatrix observations(count, space.size());
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < space.size(); ++j) {
      observations(i, j) = static_cast<float>(rng.uniform(-2.0, 2.0));
    }
  }
  return observations;
}

// Each algorithm's policy after a little training, saved and loaded: the loaded policy is of
// the same kind and acts identically, deterministically and draw for draw.
TEST_F(PolicyFile, EveryKindRoundTripsExactly) {
  const std::vector<std::pair<std::string, std::string>> cases{{"ppo", "Pendulum-v1"},
                                                               {"sac", "Pendulum-v1"},
                                                               {"td3", "Pendulum-v1"},
                                                               {"dqn", "CartPole-v1"},
                                                               {"ppo", "CartPole-v1"}};
  for (const auto& [name, id] : cases) {
    VecEnvOptions options;
    options.id = id;
    options.n_envs = 2;
    options.normalize_observation = true;
    auto env = make_vec_env(options);
    const Config algo = Config::parse(name == "ppo" ? "n_steps: 64\nbatch_size: 32\n"
                                                    : "learning_starts: 50\nbatch_size: 16\n"
                                                      "net_arch: [16]\n");
    auto algorithm = algorithm_spec(name, "test").factory(*env, algo, 3);
    algorithm->learn(256);
    const fs::path file = directory_ / (name + "_" + std::to_string(id.size()) + ".policy");
    algorithm->save_policy(file);
    const std::unique_ptr<Policy> loaded = load_policy(file);
    EXPECT_EQ(loaded->kind(), algorithm->policy().kind()) << name;
    ASSERT_TRUE(loaded->observation_normalization().has_value()) << name;

    // The loaded policy on raw observations = the trained one on normalized observations.
    Rng rng(1);
    const envs::BatchMatrix raw = observations_of(env->observation_space(), 6, rng);
    envs::BatchMatrix normalized = raw;
    for (int i = 0; i < raw.rows(); ++i) {
      normalized.row(i) = env->normalizer()
                              ->observation_statistics()
                              .normalize(raw.row(i).transpose().cast<double>(), 1e-8, 10.0)
                              .cast<float>()
                              .transpose();
    }
    for (const bool deterministic : {true, false}) {
      Rng a(5), b(5);
      envs::BatchMatrix ours, theirs;
      loaded->act(raw, deterministic, a, ours);
      algorithm->policy().act(normalized, deterministic, b, theirs);
      EXPECT_EQ(ours, theirs) << name << " deterministic " << deterministic;
    }
  }
}

TEST_F(PolicyFile, DamagedAndForeignFilesAreRefused) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  auto env = make_vec_env(options);
  auto algorithm = algorithm_spec("td3", "test").factory(*env, Config::parse("{}"), 0);
  const fs::path file = directory_ / "model.policy";
  algorithm->save_policy(file);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[bytes.size() / 2] ^= 0x10;
  const fs::path damaged = directory_ / "damaged.policy";
  std::ofstream(damaged, std::ios::binary) << bytes;
  EXPECT_NE(testing::error_message([&] { load_policy(damaged); }).find("checksum mismatch"),
            std::string::npos);
  algorithm->save(directory_ / "step_1.ckpt");
  EXPECT_EQ(testing::error_message([&] { load_policy(directory_ / "step_1.ckpt"); }),
            (directory_ / "step_1.ckpt").string() + ": a checkpoint file, not a policy file");

  // Observations of the wrong size or not finite.
  const std::unique_ptr<Policy> policy = load_policy(file);
  Rng rng(0);
  EXPECT_EQ(testing::error_message([&] { policy->act(Observation::Zero(4), true, rng); }),
            "rl::Policy::act: observations have 4 components, the policy expects 3");
  Observation nan = Observation::Zero(3);
  nan[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(testing::error_message([&] { policy->act(nan, true, rng); }),
            "rl::Policy::act: an observation is not finite");
}

}  // namespace
}  // namespace tendril::rl
