// A task outside safety/ gains the safety filter's constraint and search space by implementing
// envs::SafetyTask: constraint_of and search_space_of find it through wrappers.
#include "tendril/envs/safety_task.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"
#include "tendril/safety/constraint.hpp"
#include "tendril/safety/search_space.hpp"

namespace tendril::safety {
namespace {

// A point on a line, x' = x + a (|a| ≤ 1), observed as [x, t/T] with T = 10; safe |x| < 1.5.
class LineTask : public Env, public envs::SafetyTask {
 public:
  static constexpr double kLimit = 1.5;
  static constexpr int kHorizon = 10;

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> /*seed*/ = std::nullopt) override {
    x_ = 0.0;
    steps_ = 0;
    return observe();
  }
  Step step(const Action& action) override {
    x_ += action[0];
    ++steps_;
    Step step;
    step.observation = observe();
    return step;
  }
  void place(double x) { x_ = x; }

  std::unique_ptr<envs::SafetyConstraint> safety_constraint() const override {
    return std::make_unique<Constraint>();
  }
  std::unique_ptr<envs::SafetySearchSpace> safety_search_space() const override {
    return std::make_unique<SearchSpace>();
  }

 private:
  class Constraint : public envs::SafetyConstraint {
   public:
    double margin(const Observation& o) const override { return kLimit - std::abs(o[0]); }
    double max_margin() const override { return kLimit; }
    int64_t time_step(const Observation& o) const override { return std::llround(o[1] * 10.0); }
    int64_t horizon() const override { return kHorizon; }
    Observation sample_unsafe(Rng& /*rng*/) const override { return Eigen::Vector2f(2.0f, 0.0f); }
  };
  class SearchSpace : public envs::SafetySearchSpace {
   public:
    const std::vector<std::string>& names() const override { return names_; }
    const Eigen::VectorXd& scales() const override { return scales_; }
    Observation observation(const Eigen::VectorXd& s) const override {
      return Eigen::Vector2f(static_cast<float>(s[0] * kLimit), 0.0f);
    }
    void place(Env& env, const Eigen::VectorXd& s) const override {
      envs::find_wrapper<LineTask>(env)->place(s[0] * kLimit);
    }
    Eigen::VectorXd sample(Rng& rng) const override {
      return Eigen::VectorXd::Constant(1, rng.uniform(-1.0, 1.0));
    }

   private:
    std::vector<std::string> names_{"x"};
    Eigen::VectorXd scales_ = Eigen::VectorXd::Constant(1, kLimit);
  };

  Observation observe() const {
    return Eigen::Vector2f(static_cast<float>(x_), static_cast<float>(steps_) / kHorizon);
  }

  Space observation_space_ = Space::box(2, -10.0f, 10.0f);
  Space action_space_ = Space::box(1, -1.0f, 1.0f);
  double x_ = 0.0;
  int steps_ = 0;
};

TEST(SafetyTask, ConstraintAndSearchSpaceAreFoundThroughWrappers) {
  envs::TimeLimit env(std::make_unique<LineTask>(), LineTask::kHorizon);
  const auto constraint = constraint_of(env);
  EXPECT_DOUBLE_EQ(constraint->max_margin(), 1.5);
  EXPECT_EQ(constraint->horizon(), 10);
  EXPECT_NEAR(constraint->margin(Eigen::Vector2f(-1.25f, 0.3f)), 0.25, 1e-7);
  EXPECT_EQ(constraint->time_step(Eigen::Vector2f(0.0f, 0.3f)), 3);
  EXPECT_TRUE(constraint->unsafe(Eigen::Vector2f(1.5f, 0.0f)));  // d = 0 is unsafe (eq. 6.4)

  const auto space = search_space_of(env);
  ASSERT_EQ(space->dimension(), 1);
  EXPECT_EQ(space->names()[0], "x");
  // Placed at s = 0.5 (x = 0.75), one step of a = 0.5 ends at 1.25 with 0.25 to the bound.
  env.reset(0);
  space->place(env, Eigen::VectorXd::Constant(1, 0.5));
  const Step step = env.step(Action::Constant(1, 0.5f));
  EXPECT_FLOAT_EQ(step.observation[0], 1.25f);
  EXPECT_NEAR(constraint->margin(step.observation), 0.25, 1e-7);
}

// A task that is no SafetyTask is refused by name, wrapped or not.
TEST(SafetyTask, AnEnvironmentWithoutTheCapabilityIsRefused) {
  class Plain : public Env {
   public:
    const Space& observation_space() const override { return space_; }
    const Space& action_space() const override { return space_; }
    Observation reset(std::optional<uint64_t> = std::nullopt) override { return Observation(1); }
    Step step(const Action&) override {
      Step step;
      step.observation = Observation(1);
      return step;
    }

   private:
    Space space_ = Space::box(1, -1.0f, 1.0f);
  };
  envs::TimeLimit env(std::make_unique<Plain>(), 5);
  try {
    constraint_of(env);
    FAIL() << "constraint_of accepted an environment without a constraint";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("envs::SafetyTask"), std::string::npos) << e.what();
  }
  EXPECT_THROW(search_space_of(env), Error);
}

}  // namespace
}  // namespace tendril::safety
