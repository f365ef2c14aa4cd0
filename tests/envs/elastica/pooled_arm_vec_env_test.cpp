#include "tendril/envs/elastica/pooled_arm_vec_env.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs::elastica {
namespace {

constexpr const char* kId = "Elastica/Tracking3D-v0";
constexpr int kLimit = 25;  // steps per episode, so that a run has several auto-resets

Config params(bool lockstep) {
  return Config::parse("max_episode_steps: " + std::to_string(kLimit) +
                       "\nlockstep_rods: " + (lockstep ? "true" : "false") + "\n");
}

std::unique_ptr<VecEnv> pooled(int num_envs) {
  std::unique_ptr<VecEnv> env = make_vector(kId, params(true), num_envs);
  EXPECT_NE(dynamic_cast<PooledArmVecEnv*>(env.get()), nullptr);
  return env;
}

// What make_vec_env builds without lockstep_rods: make(id) envs (in their time limit) in
// EpisodeStatistics, on one thread.
std::unique_ptr<VecEnv> threaded(int num_envs) {
  return std::make_unique<ThreadedVecEnv>(
      num_envs, [](int) { return std::make_unique<EpisodeStatistics>(make(kId, params(false))); },
      1);
}

// Actions beyond [−1, 1] too, which the muscles saturate.
BatchMatrix random_actions(int num_envs, int size, Rng& rng) {
  BatchMatrix actions(num_envs, size);
  for (int i = 0; i < num_envs; ++i) {
    for (int j = 0; j < size; ++j) actions(i, j) = static_cast<float>(rng.uniform(-1.2, 1.2));
  }
  return actions;
}

// Every field of two vector steps, compared exactly.
void expect_same_step(const VecStep& got, const VecStep& want, int step) {
  ASSERT_EQ(got.observations.rows(), want.observations.rows());
  for (int i = 0; i < want.observations.rows(); ++i) {
    const std::string where = "step " + std::to_string(step) + ", env " + std::to_string(i);
    for (int j = 0; j < want.observations.cols(); ++j) {
      ASSERT_EQ(got.observations(i, j), want.observations(i, j)) << where << ", entry " << j;
      ASSERT_EQ(got.final_observations(i, j), want.final_observations(i, j))
          << where << ", entry " << j;
    }
    ASSERT_EQ(got.rewards[i], want.rewards[i]) << where;
    ASSERT_EQ(got.terminated[i], want.terminated[i]) << where;
    ASSERT_EQ(got.truncated[i], want.truncated[i]) << where;
    ASSERT_EQ(got.infos[i].entries(), want.infos[i].entries()) << where;
  }
}

// n = 3 (one partial block of rods) and 9 (a full block and a lone rod in the next): four
// episodes of each env with auto-resets, one of them seeded through seed_next_reset, equal bit
// for bit to the threaded vector env of single envs.
void check_matches_threaded(int num_envs) {
  std::unique_ptr<VecEnv> pool = pooled(num_envs);
  std::unique_ptr<VecEnv> reference = threaded(num_envs);
  ASSERT_EQ(pool->num_envs(), num_envs);
  ASSERT_EQ(pool->observation_space().size(), reference->observation_space().size());
  ASSERT_EQ(pool->action_space().size(), reference->action_space().size());

  const BatchMatrix& first = pool->reset(7);
  const BatchMatrix& first_reference = reference->reset(7);
  ASSERT_TRUE(first == first_reference);

  Rng rng(11);
  int episodes_ended = 0;
  for (int step = 0; step < 4 * kLimit; ++step) {
    if (step == kLimit + 3) {
      pool->seed_next_reset(num_envs - 1, 1234);
      reference->seed_next_reset(num_envs - 1, 1234);
    }
    const BatchMatrix actions = random_actions(num_envs, pool->action_space().size(), rng);
    const VecStep& got = pool->step(actions);
    const VecStep& want = reference->step(actions);
    expect_same_step(got, want, step);
    if (::testing::Test::HasFatalFailure()) return;
    for (int i = 0; i < num_envs; ++i) {
      if (!got.done(i)) continue;
      ++episodes_ended;
      EXPECT_TRUE(got.truncated[i]);  // no NaN under these actions: the time limit ends them
      EXPECT_EQ(got.infos[i].get(info_keys::kEpisodeLength), kLimit);
      // The next episode starts at rest, not where the last one ended.
      EXPECT_FALSE(got.observations.row(i) == got.final_observations.row(i));
    }
  }
  EXPECT_EQ(episodes_ended, 4 * num_envs);
}

TEST(PooledArmVecEnv, MatchesThreadedSingleEnvsBitForBitInAPartialBlock) {
  check_matches_threaded(3);
}

TEST(PooledArmVecEnv, MatchesThreadedSingleEnvsBitForBitOverTwoBlocks) {
  check_matches_threaded(9);
}

TEST(PooledArmVecEnv, SnapshotsRestoreTheRunExactly) {
  std::unique_ptr<VecEnv> pool = pooled(3);
  ASSERT_TRUE(pool->supports_snapshots());
  pool->reset(3);
  Rng rng(5);
  for (int step = 0; step < kLimit - 5; ++step) {
    pool->step(random_actions(3, pool->action_space().size(), rng));
  }
  Snapshot snapshot;
  SnapshotWriter writer(snapshot);
  pool->save_state(writer, true);

  // Ten steps on, across an episode end, then the same ten from the snapshot.
  std::vector<BatchMatrix> actions;
  std::vector<VecStep> first;
  for (int step = 0; step < 10; ++step) {
    actions.push_back(random_actions(3, pool->action_space().size(), rng));
    first.push_back(pool->step(actions.back()));
  }
  SnapshotReader reader(snapshot);
  ASSERT_TRUE(pool->load_state(reader));
  for (int step = 0; step < 10; ++step) {
    expect_same_step(pool->step(actions[step]), first[step], step);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(PooledArmVecEnv, BuiltOnlyWhenAskedAndOnlyForPositionVerlet) {
  EXPECT_EQ(make_vector(kId, params(false), 4), nullptr);
  EXPECT_EQ(make_vector(kId, Config(), 4), nullptr);
  try {
    make_vector(kId, Config::parse("lockstep_rods: true\nintegrator: bdf2\n"), 4);
    FAIL() << "an implicit rod was pooled";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lockstep_rods"), std::string::npos) << e.what();
  }
  // A single env reads the key and is the same env either way.
  EXPECT_NE(make(kId, params(true)), nullptr);
}

TEST(PooledArmVecEnv, BadActionsAreRefused) {
  std::unique_ptr<VecEnv> pool = pooled(2);
  EXPECT_THROW(pool->step(BatchMatrix::Zero(2, 12)), Error);  // before reset
  pool->reset(0);
  EXPECT_THROW(pool->step(BatchMatrix::Zero(3, 12)), Error);
  BatchMatrix actions = BatchMatrix::Zero(2, 12);
  actions(1, 4) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(pool->step(actions), Error);
  EXPECT_THROW(pool->step(BatchMatrix::Zero(2, 12)), Error);  // needs a reset after an error
  pool->reset(0);
  EXPECT_NO_THROW(pool->step(BatchMatrix::Zero(2, 12)));
}

}  // namespace
}  // namespace tendril::envs::elastica
