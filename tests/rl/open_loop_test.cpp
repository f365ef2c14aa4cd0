#include "tendril/rl/open_loop.hpp"

#include <gtest/gtest.h>

#include "tendril/core/archive.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {
namespace {

// Pushes Pendulum-v1 by a torque proportional to the observed angular velocity: a deterministic
// policy whose actions depend on what it observes.
class DampingPolicy final : public Policy {
 public:
  DampingPolicy(Space observations, Space actions)
      : Policy(std::move(observations), std::move(actions)) {}
  std::string kind() const override { return "deterministic"; }

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool, Rng&,
                   Eigen::MatrixXf& actions) const override {
    actions = (-0.5f * observations.row(2)).cwiseMax(-2.0f).cwiseMin(2.0f);
  }
  void write(ArchiveWriter&) const override {}
};

// Replaying the actions a deterministic policy took on the same environment, reset with the
// same seed, is the same episode: the same return, length and final info as running the policy
// closed loop. Episode 1 resets with seed + 1: the same actions from another start give another
// return.
TEST(OpenLoop, ReplayedActionsRepeatTheClosedLoopEpisode) {
  auto env = envs::make("Pendulum-v1");
  const DampingPolicy policy(env->observation_space(), env->action_space());
  const std::vector<Action> actions = recorded_actions(policy, *env, true, 7);
  EXPECT_EQ(actions.size(), 200u);  // Pendulum's time limit
  envs::RunSettings settings;
  settings.episodes = 1;
  settings.seed = 7;
  const envs::RunResult closed = envs::run_policy(policy, *env, settings);
  const envs::RunResult open = replay_actions(actions, *env, 2, 7);
  ASSERT_EQ(open.episodes.size(), 2u);
  EXPECT_EQ(open.episodes[0].episode_return, closed.episodes[0].episode_return);
  EXPECT_EQ(open.episodes[0].length, closed.episodes[0].length);
  EXPECT_EQ(open.episodes[1].seed, 8u);
  EXPECT_NE(open.episodes[1].episode_return, open.episodes[0].episode_return);

  // Fewer actions than the time limit: the episode ends when they run out.
  const std::vector<Action> first(actions.begin(), actions.begin() + 10);
  EXPECT_EQ(replay_actions(first, *env, 1, 7).episodes[0].length, 10);
  EXPECT_THROW(replay_actions({}, *env, 1, 7), Error);
}

}  // namespace
}  // namespace tendril::rl
