// The curriculum promotes a task with levels by its rule, and any registered task with levels
// gets one from its parameters.
#include "tendril/envs/wrappers/curriculum.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "envs/scripted_env.hpp"
#include "support/error_message.hpp"
#include "tendril/envs/beam/beam_env.hpp"
#include "tendril/envs/beam/ellipse_path.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

// A task of three levels that reports `error` as its "distance" every step and ends an episode
// after `length` steps (terminated when `terminates`).
class LevelledTask : public Env, public CurriculumTask {
 public:
  double error = 0.1;
  int length = 5;
  bool terminates = false;
  int episode_level = -1;  // the level the running episode was reset at

  const Space& observation_space() const override { return space_; }
  const Space& action_space() const override { return space_; }
  Observation reset(std::optional<uint64_t> = std::nullopt) override {
    steps_ = 0;
    episode_level = level_;
    return Observation::Zero(1);
  }
  Step step(const Action&) override {
    Step result;
    result.observation = Observation::Zero(1);
    result.terminated = terminates && ++steps_ >= length;
    result.info.set("distance", error);
    return result;
  }
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override {
    out.section("LevelledTask");
    out.put(static_cast<int64_t>(level_));
  }
  void load_state(SnapshotReader& in) override {
    in.section("LevelledTask");
    level_ = static_cast<int>(in.get_int64());
  }
  int curriculum_levels() const override { return 3; }
  int curriculum_level() const override { return level_; }
  void set_curriculum_level(int level) override {
    require(level >= 0 && level < 3, "no such level", "LevelledTask");
    level_ = level;
  }

 private:
  Space space_ = Space::box(1, -1.0f, 1.0f);
  int steps_ = 0;
  int level_ = 2;
};

// Runs `episodes` episodes of `length` steps (reset-ended, as under a time limit).
void run_episodes(Env& env, int episodes, int length) {
  for (int e = 0; e < episodes; ++e) {
    env.reset();
    for (int t = 0; t < length; ++t) {
      if (env.step(Action::Zero(1)).terminated) break;
    }
  }
}

struct Fixture {
  LevelledTask* task;
  std::unique_ptr<Curriculum> curriculum;
};

Fixture make_curriculum(const CurriculumRule& rule) {
  auto task = std::make_unique<LevelledTask>();
  LevelledTask* raw = task.get();
  return {raw, std::make_unique<Curriculum>(std::move(task), rule)};
}

TEST(Curriculum, PromotesAfterAWindowOfSuccessesAndStartsTheNextEpisodeThere) {
  CurriculumRule rule;
  rule.window = 4;
  rule.threshold = 0.06;
  rule.success_rate = 0.75;
  auto [task, curriculum] = make_curriculum(rule);
  EXPECT_EQ(task->curriculum_level(), 0);  // start_level
  task->error = 0.05;
  run_episodes(*curriculum, 3, 5);
  EXPECT_EQ(curriculum->level(), 0) << "three episodes are not yet a window of four";
  curriculum->reset();  // finishes the third
  EXPECT_EQ(curriculum->level(), 0);
  EXPECT_EQ(task->episode_level, 0);
  run_episodes(*curriculum, 1, 5);
  curriculum->reset();  // the fourth success: promoted, this episode runs at level 1
  EXPECT_EQ(curriculum->level(), 1);
  EXPECT_EQ(task->episode_level, 1);
  EXPECT_EQ(curriculum->episodes_at_level(), 0);
  const Step step = curriculum->step(Action::Zero(1));
  EXPECT_EQ(*step.info.get(Curriculum::kLevelKey), 1.0);
  // A fresh window at the new level; the last level is final.
  run_episodes(*curriculum, 10, 5);
  curriculum->reset();
  EXPECT_EQ(curriculum->level(), 2);
  run_episodes(*curriculum, 10, 5);
  EXPECT_EQ(curriculum->level(), 2);
}

TEST(Curriculum, StaysWhileTooFewEpisodesSucceed) {
  CurriculumRule rule;
  rule.window = 4;
  rule.success_rate = 0.75;
  auto [task, curriculum] = make_curriculum(rule);
  for (int e = 0; e < 20; ++e) {
    task->error = e % 2 == 0 ? 0.05 : 0.07;  // half succeed
    run_episodes(*curriculum, 1, 5);
  }
  curriculum->reset();
  EXPECT_EQ(curriculum->level(), 0);
  EXPECT_EQ(curriculum->recent_scores().size(), 4u);
}

TEST(Curriculum, TheMeanRuleAndTheEpisodeMean) {
  CurriculumRule rule;
  rule.window = 2;
  rule.rule = CurriculumRule::Rule::kMean;
  rule.threshold = 0.06;
  auto [task, curriculum] = make_curriculum(rule);
  // Episode 1: mean of (0.02, 0.02, 0.11, 0.11) = 0.065; episode 2: 0.05. Mean 0.0575 < 0.06.
  curriculum->reset();
  for (double value : {0.02, 0.02, 0.11, 0.11}) {
    task->error = value;
    curriculum->step(Action::Zero(1));
  }
  curriculum->reset();
  EXPECT_NEAR(curriculum->recent_scores().back(), 0.065, 1e-15);
  EXPECT_EQ(curriculum->level(), 0);
  task->error = 0.05;
  curriculum->step(Action::Zero(1));
  curriculum->reset();
  EXPECT_EQ(curriculum->level(), 1);
}

TEST(Curriculum, EpisodesTheTaskEndsEarlyFail) {
  CurriculumRule rule;
  rule.window = 3;
  rule.success_rate = 1.0;
  auto [task, curriculum] = make_curriculum(rule);
  task->error = 0.01;
  task->terminates = true;
  task->length = 3;
  run_episodes(*curriculum, 6, 10);  // each ends by termination after 3 steps
  EXPECT_EQ(curriculum->level(), 0);
  rule.failed_if_terminated = false;
  auto [task2, lenient] = make_curriculum(rule);
  task2->error = 0.01;
  task2->terminates = true;
  task2->length = 3;
  run_episodes(*lenient, 3, 10);
  EXPECT_EQ(lenient->level(), 1);  // promoted at the third termination
}

TEST(Curriculum, SnapshotsHoldTheLevelAndTheWindow) {
  CurriculumRule rule;
  rule.window = 3;
  auto [task, curriculum] = make_curriculum(rule);
  task->error = 0.01;
  run_episodes(*curriculum, 4, 2);  // promoted after 3, one more at level 1
  curriculum->step(Action::Zero(1));
  ASSERT_EQ(curriculum->level(), 1);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  curriculum->save_state(out);

  auto [copy_task, copy] = make_curriculum(rule);
  SnapshotReader in(bytes);
  copy->load_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(copy->level(), 1);
  EXPECT_EQ(copy->episodes_at_level(), curriculum->episodes_at_level());
  EXPECT_EQ(copy->recent_scores(), curriculum->recent_scores());
  // Both promote on the same episode.
  copy_task->error = 0.01;
  for (int e = 0; e < 3; ++e) {
    run_episodes(*curriculum, 1, 2);
    run_episodes(*copy, 1, 2);
    EXPECT_EQ(copy->level(), curriculum->level()) << e;
  }
}

TEST(Curriculum, BadRulesAndTasksWithoutLevelsAreRefused) {
  EXPECT_NE(tendril::testing::error_message([] {
              Curriculum(std::make_unique<envs::testing::ScriptedEnv>(), CurriculumRule{});
            }).find("no curriculum levels"),
            std::string::npos);
  CurriculumRule rule;
  rule.start_level = 3;
  EXPECT_NE(tendril::testing::error_message([&] { make_curriculum(rule); }).find("start_level"),
            std::string::npos);
  EXPECT_NE(tendril::testing::error_message([] {
              CurriculumRule::from_config(Config::parse("{window: 0}", "c.yaml"));
            }).find("window"),
            std::string::npos);
  EXPECT_NE(tendril::testing::error_message([] {
              CurriculumRule::from_config(Config::parse("{rule: best}", "c.yaml"));
            }).find("rule"),
            std::string::npos);
  auto [task, curriculum] = make_curriculum(CurriculumRule{.metric = "progress"});
  curriculum->reset();
  EXPECT_NE(
      tendril::testing::error_message([&] { curriculum->step(Action::Zero(1)); }).find("progress"),
      std::string::npos);
}

// From an experiment's parameters: the ellipse task starts at its fixed-parameter level inside
// the time limit, and a task without levels or a misspelt key is refused.
TEST(Curriculum, AnyTaskWithLevelsGetsOneFromItsParameters) {
  auto env = make("Beam/EllipseFollow-v0",
                  Config::parse("curriculum: {window: 20, threshold: 0.06, rule: mean}"));
  ASSERT_NE(dynamic_cast<TimeLimit*>(env.get()), nullptr);
  auto* curriculum = find_wrapper<Curriculum>(*env);
  ASSERT_NE(curriculum, nullptr);
  EXPECT_EQ(curriculum->level(), 0);
  EXPECT_EQ(curriculum->levels(), 3);
  EXPECT_EQ(curriculum->rule().rule, CurriculumRule::Rule::kMean);
  env->reset(3);
  const auto& ellipse =
      dynamic_cast<const beam::EllipsePath&>(find_wrapper<beam::BeamEnv>(*env)->target());
  EXPECT_EQ(ellipse.semi_major_axis(), 0.2);
  EXPECT_EQ(ellipse.angular_velocity(), 0.5);
  EXPECT_EQ(*env->step(Action::Zero(5)).info.get(Curriculum::kLevelKey), 0.0);

  EXPECT_NE(tendril::testing::error_message([] {
              make("Pendulum-v1", Config::parse("curriculum: {window: 3}", "p.yaml"));
            }).find("no curriculum levels"),
            std::string::npos);
  EXPECT_NE(tendril::testing::error_message([] {
              make("Beam/EllipseFollow-v0", Config::parse("curriculum: {windw: 3}", "e.yaml"));
            }).find("windw"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::envs
