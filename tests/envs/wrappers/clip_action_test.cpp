#include "tendril/envs/wrappers/clip_action.hpp"

#include <gtest/gtest.h>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/cart_pole.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

TEST(ClipAction, ClipsEachComponentToTheInnerBounds) {
  auto inner = std::make_unique<ScriptedEnv>();
  ScriptedEnv* scripted = inner.get();
  ClipAction env(std::move(inner));
  EXPECT_EQ(env.action_space().low(), Eigen::Vector2f(-2.0f, 0.0f));  // bounds stay visible
  env.reset(0);
  env.step(Eigen::Vector2f(-5.0f, 0.25f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(-2.0f, 0.25f));
  env.step(Eigen::Vector2f(2.5f, 9.0f));
  EXPECT_EQ(scripted->last_action(), Eigen::Vector2f(2.5f, 1.0f));
}

TEST(ClipAction, StillRejectsInvalidActions) {
  ClipAction env(std::make_unique<ScriptedEnv>());
  env.reset(0);
  EXPECT_THROW(env.step(Eigen::Vector2f(0.0f, INFINITY)), Error);
  EXPECT_THROW(env.step(Action::Zero(1)), Error);
  EXPECT_THROW(ClipAction(std::make_unique<CartPole>()), Error);
}

}  // namespace
}  // namespace tendril::envs
