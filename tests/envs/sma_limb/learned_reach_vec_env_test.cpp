// The batched vector env of SmaLimb/LearnedReach-v0 against N single envs in a ThreadedVecEnv
// (what make_vec_env built before): identical observations, rewards, flags, final observations
// and infos step by step, with the stand-in linear model (bit-exact in either arrangement).
#include "tendril/envs/sma_limb/learned_reach_vec_env.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/learned_reach_env.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs::sma_limb {
namespace {

// Short episodes, a loose goal and frequent full resets, so that every kind of ending happens.
const char* const kParams =
    "seed: 3\nhistory: 4\nmax_episode_steps: 30\ntolerance_start: 25\ntolerance_end: 20\n"
    "full_reset_probability: 0.3\n";

TEST(LearnedReachVecEnv, StepsAsNSingleEnvsInAThreadedVecEnv) {
  const int n = 4;
  std::unique_ptr<VecEnv> batched = make_vector(LearnedReachEnv::kId, Config::parse(kParams), n);
  ASSERT_NE(dynamic_cast<LearnedReachVecEnv*>(batched.get()), nullptr);
  ThreadedVecEnv threaded(n, [](int) -> std::unique_ptr<Env> {
    return std::make_unique<EpisodeStatistics>(make(LearnedReachEnv::kId, Config::parse(kParams)));
  });
  ASSERT_EQ(batched->observation_space().size(), threaded.observation_space().size());
  EXPECT_TRUE(batched->reset(11) == threaded.reset(11));
  Rng rng(5);
  int terminated = 0, truncated = 0;
  for (int t = 0; t < 400; ++t) {
    BatchMatrix actions(n, 2);
    for (Eigen::Index i = 0; i < actions.size(); ++i) {
      actions.data()[i] = static_cast<float>(rng.uniform(-10.0, 10.0));
    }
    const VecStep& a = batched->step(actions);
    const VecStep& b = threaded.step(actions);
    ASSERT_TRUE(a.observations == b.observations) << "step " << t;
    ASSERT_TRUE(a.final_observations == b.final_observations) << "step " << t;
    ASSERT_TRUE(a.rewards == b.rewards) << "step " << t;
    ASSERT_EQ(a.terminated, b.terminated) << "step " << t;
    ASSERT_EQ(a.truncated, b.truncated) << "step " << t;
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(a.infos[i].entries(), b.infos[i].entries()) << "step " << t << " env " << i;
      terminated += a.terminated[i];
      truncated += a.truncated[i];
    }
  }
  EXPECT_GT(terminated, 10);
  EXPECT_GT(truncated, 10);
}

TEST(LearnedReachVecEnv, SnapshotsRestoreTheRunExactly) {
  auto env = make_vector(LearnedReachEnv::kId, Config::parse(kParams), 3);
  env->reset(2);
  BatchMatrix actions = BatchMatrix::Constant(3, 2, 6.0f);
  for (int t = 0; t < 45; ++t) env->step(actions);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  env->save_state(out, true);
  std::vector<BatchMatrix> expected;
  for (int t = 0; t < 40; ++t) expected.push_back(env->step(actions).observations);
  auto restored = make_vector(LearnedReachEnv::kId, Config::parse(kParams), 3);
  SnapshotReader in(bytes);
  ASSERT_TRUE(restored->load_state(in));
  for (int t = 0; t < 40; ++t) ASSERT_TRUE(restored->step(actions).observations == expected[t]);
}

TEST(LearnedReachVecEnv, BadInputIsRefused) {
  auto env = make_vector(LearnedReachEnv::kId, Config::parse(kParams), 2);
  EXPECT_THROW(env->step(BatchMatrix::Zero(2, 2)), Error);  // before reset
  env->reset(0);
  EXPECT_THROW(env->step(BatchMatrix::Zero(3, 2)), Error);
  EXPECT_THROW(make_vector(LearnedReachEnv::kId, Config::parse("histroy: 3"), 2), Error);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
