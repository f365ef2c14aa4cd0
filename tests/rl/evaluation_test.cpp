#include "tendril/rl/evaluation.hpp"

#include <gtest/gtest.h>

#include "tendril/core/archive.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::rl {
namespace {

// Pushes Pendulum-v1 by a fixed torque proportional to the observed angular velocity: a
// deterministic policy whose actions depend on what it observes.
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
// same seed, is the same episode: the same return, length and final info as evaluating the
// policy closed loop. From another start the same actions give another return.
TEST(Evaluation, ReplayedActionsRepeatTheClosedLoopEpisode) {
  auto env = envs::make("Pendulum-v1");
  const DampingPolicy policy(env->observation_space(), env->action_space());
  const std::vector<Action> actions = recorded_actions(policy, *env, true, 7);
  EXPECT_EQ(actions.size(), 200u);  // Pendulum's time limit
  const EvaluationResult closed = evaluate_policy(policy, *env, 1, true, 7);
  const EvaluationResult open = replay_actions(actions, *env, 2, 7);
  ASSERT_EQ(open.returns.size(), 2u);
  ASSERT_EQ(open.final_infos.size(), 2u);
  EXPECT_EQ(open.returns[0], closed.returns[0]);
  EXPECT_EQ(open.lengths[0], closed.lengths[0]);
  EXPECT_NE(open.returns[1], open.returns[0]);  // the second reset is not seeded with 7

  // Fewer actions than the time limit: the episode ends when they run out.
  const std::vector<Action> first(actions.begin(), actions.begin() + 10);
  EXPECT_EQ(replay_actions(first, *env, 1, 7).lengths[0], 10);
  EXPECT_THROW(replay_actions({}, *env, 1, 7), Error);
}

// Over a vector env, each env runs its share of the episodes whole — the same episodes, one by
// one, as evaluating each env alone from the same seed — so the short episodes that end first
// are not favoured. Pendulum's episodes all last 200 steps; the returns differ by start.
TEST(Evaluation, AVectorEnvRunsEachEnvsShareOfWholeEpisodes) {
  envs::ThreadedVecEnv vector(3, [](int) -> std::unique_ptr<Env> {
    return std::make_unique<envs::EpisodeStatistics>(envs::make("Pendulum-v1"));
  });
  const DampingPolicy policy(vector.observation_space(), vector.action_space());
  const EvaluationResult result = evaluate_policy(policy, vector, 7, true, 5);
  ASSERT_EQ(result.returns.size(), 7u);  // env 0: 2, env 1: 2, env 2: 3 episodes
  for (int64_t length : result.lengths) EXPECT_EQ(length, 200);
  // Env i, reset with seed 5 + i and then unseeded, as a single env evaluated alone.
  std::size_t index = 0;
  for (int i = 0; i < 3; ++i) {
    auto single = envs::make("Pendulum-v1");
    const EvaluationResult alone = evaluate_policy(policy, *single, (7 + i) / 3, true, 5 + i);
    for (double value : alone.returns) EXPECT_NEAR(result.returns[index++], value, 1e-3) << i;
  }
  EXPECT_FALSE(result.success_rate().has_value());  // Pendulum reports no success
}

TEST(Evaluation, SuccessRateIsTheShareOfEpisodesEndingInSuccess) {
  EvaluationResult result;
  result.final_infos.resize(4);
  result.final_infos[0].set("is_success", 1.0);
  result.final_infos[1].set("is_success", 0.0);
  result.final_infos[2].set("is_success", 1.0);
  // The fourth ended without reporting (a timeout of an env that sets is_success on goals only).
  EXPECT_DOUBLE_EQ(*result.success_rate(), 0.5);
}

}  // namespace
}  // namespace tendril::rl
