#include "tendril/rl/normalizer_state.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

VecEnvOptions pendulum(int n_envs, bool normalize_observation, bool normalize_reward) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  options.n_envs = n_envs;
  options.normalize_observation = normalize_observation;
  options.normalize_reward = normalize_reward;
  return options;
}

// A VecEnv whose shared statistics and running returns are past their initial values.
std::unique_ptr<envs::VecEnv> stepped(const VecEnvOptions& options) {
  auto env = make_vec_env(options);
  env->reset(11);
  envs::BatchMatrix actions(options.n_envs, 1);
  for (int t = 0; t < 50; ++t) {
    for (int i = 0; i < options.n_envs; ++i) actions(i, 0) = 0.5f * static_cast<float>(i) - 0.3f;
    env->step(actions);
  }
  return env;
}

class NormalizerStateTest : public testing::ScratchDirectoryTest {
 protected:
  NormalizerStateTest() : ScratchDirectoryTest("normalizer_state_test") {}

  fs::path save(const envs::VecEnv& env, const std::string& name) {
    const fs::path file = directory_ / name;
    CheckpointWriter writer;
    save_normalizers(env, writer);
    writer.write_int("marker", 1);  // a checkpoint of an unnormalized env is not empty
    writer.commit(file);
    return file;
  }

  // The message of loading `file` into `env`, which must leave `env` as it was.
  std::string load_error(envs::VecEnv& env, const fs::path& file) {
    const envs::VecNormalize* normalizer = env.normalizer();
    const auto observations =
        normalizer ? normalizer->observation_statistics().to_array() : std::vector<double>{};
    const auto returns =
        normalizer ? normalizer->return_statistics().to_array() : std::vector<double>{};
    const Eigen::VectorXd running = normalizer ? normalizer->returns() : Eigen::VectorXd();
    const std::string message = testing::error_message([&] {
      CheckpointReader reader(file);
      prepare_normalizers(env, reader)();
    });
    if (normalizer != nullptr) {
      EXPECT_EQ(normalizer->observation_statistics().to_array(), observations);
      EXPECT_EQ(normalizer->return_statistics().to_array(), returns);
      EXPECT_EQ(normalizer->returns(), running);
    }
    return message;
  }
};

TEST_F(NormalizerStateTest, SaveThenLoadRoundTripsExactly) {
  const auto trained = stepped(pendulum(3, true, true));
  const envs::VecNormalize& source = *trained->normalizer();
  ASSERT_EQ(source.returns().size(), 3);
  ASSERT_NE(source.returns()[0], 0.0);
  const fs::path file = save(*trained, "both.pt");

  auto restored = make_vec_env(pendulum(3, true, true));
  CheckpointReader reader(file);
  const auto install = prepare_normalizers(*restored, reader);
  EXPECT_EQ(restored->normalizer()->observation_statistics(), envs::RunningMeanStd(3));
  install();
  const envs::VecNormalize& target = *restored->normalizer();
  EXPECT_EQ(target.observation_statistics(), source.observation_statistics());
  EXPECT_EQ(target.return_statistics(), source.return_statistics());
  EXPECT_EQ(target.returns(), source.returns());

  // Without a normalizer there is nothing to save or load.
  auto plain = make_vec_env(pendulum(3, false, false));
  CheckpointReader plain_reader(save(*plain, "plain.pt"));
  EXPECT_NO_THROW(prepare_normalizers(*plain, plain_reader)());
}

TEST_F(NormalizerStateTest, MismatchedCheckpointsAreNamedAndChangeNothing) {
  const fs::path both = save(*stepped(pendulum(3, true, true)), "both.pt");
  const fs::path observations_only = save(*stepped(pendulum(3, true, false)), "obs.pt");
  const fs::path plain = save(*stepped(pendulum(3, false, false)), "plain.pt");

  auto fewer_envs = make_vec_env(pendulum(2, true, true));
  EXPECT_NE(load_error(*fewer_envs, both).find("running returns of 3 environments, this run has 2"),
            std::string::npos);
  auto unnormalized = make_vec_env(pendulum(3, false, false));
  EXPECT_NE(load_error(*unnormalized, both)
                .find("holds observation statistics ('normalizer_observation_statistics') but "
                      "this environment does not normalize observations"),
            std::string::npos);
  auto rewards_missing = make_vec_env(pendulum(3, true, true));
  EXPECT_NE(load_error(*rewards_missing, observations_only)
                .find("this environment normalizes rewards but the checkpoint holds no statistics"),
            std::string::npos);
  auto normalized = make_vec_env(pendulum(3, true, false));
  const std::string message = load_error(*normalized, plain);
  EXPECT_NE(message.find("normalizes observations but the checkpoint holds no statistics"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(plain.string()), std::string::npos) << message;
}

TEST_F(NormalizerStateTest, InvalidStatisticsAreNamedAndChangeNothing) {
  const auto write = [&](const std::string& name, const std::vector<double>& observation) {
    const fs::path file = directory_ / name;
    CheckpointWriter writer;
    writer.write_doubles("normalizer_observation_statistics", observation);
    writer.write_doubles("normalizer_return_statistics", {5.0, 0.0, 2.0});
    writer.write_doubles("normalizer_returns", {0.0, 0.0, 0.0});
    writer.commit(file);
    return file;
  };
  auto env = stepped(pendulum(3, true, true));
  const std::string negative =
      load_error(*env, write("negative.pt", {5.0, 0.0, 0.0, 0.0, 1.0, -1.0, 1.0}));
  EXPECT_NE(negative.find("'normalizer_observation_statistics': variance 1 is negative"),
            std::string::npos)
      << negative;
  const std::string wrong_size = load_error(*env, write("size.pt", {5.0, 0.0, 0.0, 1.0, 1.0}));
  EXPECT_NE(wrong_size.find("expected 7 numbers"), std::string::npos) << wrong_size;
}

}  // namespace
}  // namespace tendril::rl
