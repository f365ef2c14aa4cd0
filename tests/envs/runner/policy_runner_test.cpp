#include "tendril/envs/runner/policy_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs {
namespace {

// Pushes Pendulum-v1 by a torque proportional to the observed angular velocity: deterministic,
// and its actions depend on what it observes.
class DampingPolicy final : public Policy {
 public:
  explicit DampingPolicy(const Env& env)
      : observations_(env.observation_space()), actions_(env.action_space()) {}
  const Space& observation_space() const override { return observations_; }
  const Space& action_space() const override { return actions_; }
  void begin_episode(const Observation&) const override { ++episodes_begun; }
  Action act(const Observation& observation, bool, Rng&) const override {
    return Action::Constant(1, std::clamp(-0.5f * observation[2], -2.0f, 2.0f));
  }
  mutable int episodes_begun = 0;

 private:
  Space observations_, actions_;
};

RunSettings episodes(int64_t count, uint64_t seed) {
  RunSettings settings;
  settings.episodes = count;
  settings.seed = seed;
  return settings;
}

// Episode k resets with seed + k: any one episode of a run is the run of that episode alone.
TEST(PolicyRunner, EpisodeKIsTheEpisodeOfSeedPlusK) {
  auto env = make("Pendulum-v1");
  const DampingPolicy policy(*env);
  const RunResult run = run_policy(policy, *env, episodes(4, 10));
  ASSERT_EQ(run.episodes.size(), 4u);
  EXPECT_EQ(policy.episodes_begun, 4);
  EXPECT_EQ(run.steps, 800);  // Pendulum's 200-step time limit
  for (int k = 0; k < 4; ++k) {
    const EpisodeOutcome& episode = run.episodes[k];
    EXPECT_EQ(episode.index, k);
    EXPECT_EQ(episode.seed, 10u + k);
    EXPECT_TRUE(episode.truncated && !episode.terminated && episode.finished);
    const RunResult alone = run_policy(policy, *env, episodes(1, 10 + k));
    EXPECT_EQ(alone.episodes[0].episode_return, episode.episode_return) << k;
  }
  EXPECT_NE(run.episodes[0].episode_return, run.episodes[1].episode_return);
  EXPECT_EQ(run.finished_episodes(), 4);
  EXPECT_FALSE(run.success_rate().has_value());  // Pendulum reports no success
}

// A step budget cuts the last episode short and says so; observers see every step in order.
TEST(PolicyRunner, AStepBudgetCutsTheLastEpisode) {
  struct Counter : RunObserver {
    int starts = 0, ends = 0, unfinished = 0;
    int64_t steps = 0, last_step_index = -1;
    void on_episode_start(int64_t, uint64_t, const Observation&, const Env&) override {
      ++starts;
      last_step_index = -1;
    }
    void on_step(const StepView& step) override {
      EXPECT_EQ(step.step, last_step_index + 1);
      last_step_index = step.step;
      ++steps;
    }
    void on_episode_end(const EpisodeOutcome& outcome) override {
      ++ends;
      unfinished += outcome.finished ? 0 : 1;
    }
  } counter;
  auto env = make("Pendulum-v1");
  const DampingPolicy policy(*env);
  RunSettings settings;
  settings.steps = 450;
  const RunResult run = run_policy(policy, *env, settings, {&counter});
  EXPECT_EQ(run.steps, 450);
  ASSERT_EQ(run.episodes.size(), 3u);
  EXPECT_FALSE(run.episodes[2].finished);
  EXPECT_EQ(run.episodes[2].length, 50);
  EXPECT_EQ(run.finished_episodes(), 2);
  EXPECT_EQ(counter.starts, 3);
  EXPECT_EQ(counter.ends, 3);
  EXPECT_EQ(counter.unfinished, 1);
  EXPECT_EQ(counter.steps, 450);
  // The statistics are those of the finished episodes.
  EXPECT_DOUBLE_EQ(run.mean_return(),
                   (run.episodes[0].episode_return + run.episodes[1].episode_return) / 2.0);
}

// Over a vector env, episode k still resets with seed + k whichever env runs it, so a
// deterministic policy on independent envs gives the single env's episodes, in index order.
TEST(PolicyRunner, AVectorEnvRunsTheSameEpisodes) {
  ThreadedVecEnv vector(3, [](int) -> std::unique_ptr<Env> {
    return std::make_unique<EpisodeStatistics>(make("Pendulum-v1"));
  });
  auto single = make("Pendulum-v1");
  const DampingPolicy policy(*single);
  const RunResult batched = run_policy(policy, vector, episodes(7, 5));
  const RunResult alone = run_policy(policy, *single, episodes(7, 5));
  ASSERT_EQ(batched.episodes.size(), 7u);
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(batched.episodes[k].index, k);
    EXPECT_EQ(batched.episodes[k].length, 200);
    EXPECT_NEAR(batched.episodes[k].episode_return, alone.episodes[k].episode_return, 1e-3) << k;
  }
}

TEST(PolicyRunner, SuccessRateIsTheShareOfFinishedEpisodesEndingInSuccess) {
  RunResult result;
  result.episodes.resize(5);
  result.episodes[0].final_info.set("is_success", 1.0);
  result.episodes[1].final_info.set("is_success", 0.0);
  result.episodes[2].final_info.set("is_success", 1.0);
  // The fourth ended without reporting (a timeout of an env that sets is_success on goals only);
  // the fifth was cut short and does not count.
  result.episodes[4].finished = false;
  result.episodes[4].final_info.set("is_success", 1.0);
  EXPECT_DOUBLE_EQ(*result.success_rate(), 0.5);
}

TEST(PolicyRunner, RefusesBadSettingsAndMismatchedSpaces) {
  auto env = make("Pendulum-v1");
  const DampingPolicy policy(*env);
  RunSettings both = episodes(1, 0);
  both.steps = 5;
  EXPECT_THROW(run_policy(policy, *env, both), Error);
  EXPECT_THROW(run_policy(policy, *env, RunSettings{}), Error);
  auto cart_pole = make("CartPole-v1");
  EXPECT_THROW(run_policy(policy, *cart_pole, episodes(1, 0)), Error);
}

}  // namespace
}  // namespace tendril::envs
