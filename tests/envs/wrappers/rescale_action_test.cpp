#include "tendril/envs/wrappers/rescale_action.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/cart_pole.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

// ScriptedEnv's action bounds are low = (−2, 0), high = (3, 1).
TEST(RescaleAction, MapsTheUnitCubeOntoTheInnerBounds) {
  auto inner = std::make_unique<ScriptedEnv>();
  ScriptedEnv* scripted = inner.get();
  RescaleAction env(std::move(inner));
  EXPECT_EQ(env.action_space().describe(), "Box(2, [-1, 1])");
  env.reset(0);
  env.step(Eigen::Vector2f(-1.0f, 1.0f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(-2.0f, 1.0f));
  env.step(Eigen::Vector2f(1.0f, -1.0f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(3.0f, 0.0f));
  env.step(Eigen::Vector2f(0.0f, 0.5f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(0.5f, 0.75f));  // low + (a + 1)(high − low)/2
}

TEST(RescaleAction, ClipsToTheUnitCubeFirst) {
  auto inner = std::make_unique<ScriptedEnv>();
  ScriptedEnv* scripted = inner.get();
  RescaleAction env(std::move(inner));
  env.reset(0);
  env.step(Eigen::Vector2f(7.0f, -40.0f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(3.0f, 0.0f));
  EXPECT_THROW(env.step(Eigen::Vector2f(std::nanf(""), 0.0f)), Error);
  EXPECT_THROW(env.step(Action::Zero(3)), Error);
}

class UnboundedActions : public ScriptedEnv {
 public:
  const Space& action_space() const override { return space_; }

 private:
  Space space_ = Space::box(Eigen::Vector2f(-1.0f, 0.0f),
                            Eigen::Vector2f(1.0f, std::numeric_limits<float>::infinity()));
};

TEST(RescaleAction, RequiresFiniteBoxBounds) {
  EXPECT_THROW(RescaleAction(std::make_unique<UnboundedActions>()), Error);
  EXPECT_THROW(RescaleAction(std::make_unique<CartPole>()), Error);
}

}  // namespace
}  // namespace tendril::envs
