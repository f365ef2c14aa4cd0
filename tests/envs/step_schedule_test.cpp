// The environment-side schedule: constant or linear in the environment's own step count.
#include "tendril/envs/step_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

using testing::error_message;

TEST(StepSchedule, LinearFollowsTheSeedsCurriculumAndHoldsItsEnd) {
  // λ_u(t) = 0.01 + (t / T)·(0.05 − 0.01), seed 004 Sec. 3.1.3, with T = 1000.
  const StepSchedule schedule = StepSchedule::linear(0.01, 0.05, 1000);
  EXPECT_DOUBLE_EQ(schedule.value(0), 0.01);
  EXPECT_DOUBLE_EQ(schedule.value(250), 0.02);
  EXPECT_DOUBLE_EQ(schedule.value(500), 0.03);
  EXPECT_DOUBLE_EQ(schedule.value(999), 0.01 + 0.999 * 0.04);
  EXPECT_DOUBLE_EQ(schedule.value(1000), 0.05);
  EXPECT_DOUBLE_EQ(schedule.value(5000), 0.05);
  EXPECT_FALSE(schedule.is_constant());
}

TEST(StepSchedule, ConstantIsTheSameAtEveryStep) {
  const StepSchedule schedule = StepSchedule::constant(0.05);
  EXPECT_TRUE(schedule.is_constant());
  EXPECT_EQ(schedule.value(0), 0.05);
  EXPECT_EQ(schedule.value(123456789), 0.05);
}

TEST(StepSchedule, ReadsAValueOrAScheduleFromParams) {
  const Config absent = Config::parse("{}");
  EXPECT_EQ(StepSchedule::from_config(absent, "action_penalty", 0.05).value(7), 0.05);

  const Config constant = Config::parse("{action_penalty: 0.02}");
  EXPECT_EQ(StepSchedule::from_config(constant, "action_penalty", 0.05).value(7), 0.02);

  const Config linear =
      Config::parse("{action_penalty_schedule: {start: 0.01, end: 0.05, steps: 125000}}");
  const StepSchedule schedule = StepSchedule::from_config(linear, "action_penalty", 0.05);
  EXPECT_EQ(schedule.steps(), 125000);
  EXPECT_DOUBLE_EQ(schedule.value(62500), 0.03);
  EXPECT_NO_THROW(linear.reject_unknown());
}

TEST(StepSchedule, BadOrConflictingParamsAreNamed) {
  const Config both = Config::parse(
      "{action_penalty: 0.05, action_penalty_schedule: {start: 0, end: 1, steps: 9}}", "exp.yaml");
  EXPECT_NE(error_message([&] {
              StepSchedule::from_config(both, "action_penalty", 0.0);
            }).find("not both"),
            std::string::npos);
  const Config zero_steps =
      Config::parse("{action_penalty_schedule: {start: 0, end: 1, steps: 0}}", "exp.yaml");
  EXPECT_NE(error_message([&] {
              StepSchedule::from_config(zero_steps, "action_penalty", 0.0);
            }).find("action_penalty_schedule.steps"),
            std::string::npos);
  const Config missing =
      Config::parse("{action_penalty_schedule: {start: 0, steps: 10}}", "exp.yaml");
  EXPECT_NE(
      error_message([&] { StepSchedule::from_config(missing, "action_penalty", 0.0); }).find("end"),
      std::string::npos);
  const Config extra = Config::parse(
      "{action_penalty_schedule: {start: 0, end: 1, steps: 10, shape: cosine}}", "exp.yaml");
  EXPECT_NE(
      error_message([&] { StepSchedule::from_config(extra, "action_penalty", 0.0); }).find("shape"),
      std::string::npos);
  EXPECT_THROW(StepSchedule::linear(0.0, 1.0, 0), Error);
  EXPECT_THROW(StepSchedule::constant(NAN), Error);
}

}  // namespace
}  // namespace tendril::envs
