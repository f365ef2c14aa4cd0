#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

ThreadedVecEnv make_vec(const std::string& id, int num_envs, int num_threads) {
  return ThreadedVecEnv(
      num_envs, [&](int) { return make(id); }, num_threads);
}

BatchMatrix random_actions(const ThreadedVecEnv& vec, Rng& rng) {
  BatchMatrix actions(vec.num_envs(), vec.action_space().size());
  for (int i = 0; i < vec.num_envs(); ++i)
    actions.row(i) = vec.action_space().sample(rng).transpose();
  return actions;
}

TEST(ThreadedVecEnv, ObservationsAreOneRowMajorBufferAndEnvISeededWithSeedPlusI) {
  ThreadedVecEnv vec = make_vec("Pendulum-v1", 4, 1);
  const BatchMatrix& observations = vec.reset(100);
  ASSERT_EQ(observations.rows(), 4);
  ASSERT_EQ(observations.cols(), 3);
  for (int i = 0; i < 4; ++i) {
    Pendulum alone;
    const Observation expected = alone.reset(100 + i);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(observations.data()[i * 3 + j], expected[j]) << i << "," << j;
    }
  }
}

TEST(ThreadedVecEnv, AutoResetKeepsTheFinalObservation) {
  // ScriptedEnv observes [steps, resets, seed]; a 2-step limit on env 0, 3 steps on env 1.
  std::vector<std::unique_ptr<Env>> envs;
  envs.push_back(std::make_unique<EpisodeStatistics>(
      std::make_unique<TimeLimit>(std::make_unique<ScriptedEnv>(), 2)));
  envs.push_back(std::make_unique<EpisodeStatistics>(
      std::make_unique<ScriptedEnv>(ScriptedEnv::Options{0.5, 3})));
  ThreadedVecEnv vec(std::move(envs), 2);
  vec.reset(10);
  const BatchMatrix actions = BatchMatrix::Zero(2, 2);

  const VecStep& first = vec.step(actions);
  EXPECT_FALSE(first.done(0) || first.done(1));
  EXPECT_EQ(first.final_observations, first.observations);

  const VecStep& second = vec.step(actions);
  EXPECT_TRUE(second.truncated[0]);
  EXPECT_FALSE(second.terminated[0]);
  EXPECT_EQ(second.final_observations.row(0), Eigen::RowVector3f(2, 1, 10));  // last of episode 1
  EXPECT_EQ(second.observations.row(0), Eigen::RowVector3f(0, 2, 10));        // first of episode 2
  EXPECT_EQ(second.infos[0].get("episode_length"), 2.0);
  EXPECT_FALSE(second.done(1));

  const VecStep& third = vec.step(actions);
  EXPECT_TRUE(third.terminated[1]);
  EXPECT_FALSE(third.truncated[1]);
  EXPECT_EQ(third.final_observations.row(1), Eigen::RowVector3f(3, 1, 11));
  EXPECT_EQ(third.observations.row(1), Eigen::RowVector3f(0, 2, 11));
  EXPECT_EQ(third.rewards[1], 0.5f);
  EXPECT_EQ(third.infos[1].get("episode_return"), 1.5);
  EXPECT_EQ(third.infos[1].get("is_success"), 1.0);
  EXPECT_EQ(third.observations.row(0), Eigen::RowVector3f(1, 2, 10));
}

// Runs `steps` random steps and returns every observation, reward and flag in one buffer.
std::vector<float> trace(const std::string& id, int num_envs, int num_threads, uint64_t seed,
                         int steps) {
  ThreadedVecEnv vec = make_vec(id, num_envs, num_threads);
  Rng rng(seed, 99);
  std::vector<float> out;
  const auto append = [&](const BatchMatrix& m) {
    out.insert(out.end(), m.data(), m.data() + m.size());
  };
  append(vec.reset(seed));
  for (int t = 0; t < steps; ++t) {
    const VecStep& step = vec.step(random_actions(vec, rng));
    append(step.observations);
    append(step.final_observations);
    out.insert(out.end(), step.rewards.data(), step.rewards.data() + step.rewards.size());
    for (int i = 0; i < num_envs; ++i) {
      out.push_back(step.terminated[i]);
      out.push_back(step.truncated[i]);
    }
  }
  return out;
}

TEST(ThreadedVecEnv, ThreadedEqualsSynchronousBitForBit) {
  for (const std::string id : {"Pendulum-v1", "CartPole-v1"}) {
    const std::vector<float> synchronous = trace(id, 5, 1, 42, 600);
    const std::vector<float> threaded = trace(id, 5, 3, 42, 600);
    ASSERT_EQ(synchronous.size(), threaded.size());
    EXPECT_EQ(std::memcmp(synchronous.data(), threaded.data(), synchronous.size() * sizeof(float)),
              0)
        << id;
  }
}

TEST(ThreadedVecEnv, SameSeedSameRunDifferentSeedDifferentRun) {
  EXPECT_EQ(trace("CartPole-v1", 3, 2, 7, 300), trace("CartPole-v1", 3, 2, 7, 300));
  EXPECT_NE(trace("CartPole-v1", 3, 2, 7, 300), trace("CartPole-v1", 3, 2, 8, 300));
}

TEST(ThreadedVecEnv, AnEnvironmentErrorInAWorkerReachesTheCallerUnchanged) {
  ThreadedVecEnv vec = make_vec("Pendulum-v1", 4, 2);
  vec.reset(0);
  BatchMatrix actions = BatchMatrix::Zero(4, 1);
  actions(2, 0) = std::nanf("");
  try {
    vec.step(actions);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "Pendulum-v1: action component 0 is not finite");
  }
  actions(2, 0) = 0.0f;
  EXPECT_THROW(vec.step(actions), Error);  // must reset after an error
  vec.reset(0);
  EXPECT_NO_THROW(vec.step(actions));
}

TEST(ThreadedVecEnv, RejectsBadShapes) {
  ThreadedVecEnv vec = make_vec("Pendulum-v1", 2, 1);
  EXPECT_THROW(vec.step(BatchMatrix::Zero(2, 1)), Error);  // before reset
  vec.reset(0);
  EXPECT_THROW(vec.step(BatchMatrix::Zero(3, 1)), Error);
  EXPECT_THROW(vec.step(BatchMatrix::Zero(2, 2)), Error);
  std::vector<std::unique_ptr<Env>> mixed;
  mixed.push_back(make("Pendulum-v1"));
  mixed.push_back(make("CartPole-v1"));
  EXPECT_THROW(ThreadedVecEnv(std::move(mixed)), Error);
  EXPECT_THROW(make_vec("Pendulum-v1", 0, 1), Error);
}

}  // namespace
}  // namespace tendril::envs
