#include "tendril/core/space.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "tendril/core/env.hpp"
#include "tendril/core/error.hpp"

namespace tendril {
namespace {

TEST(Space, BoxContainsAndSamplesWithinBounds) {
  const Space box = Space::box(3, -2.0f, 1.0f);
  Rng rng(0);
  for (int i = 0; i < 100; ++i) EXPECT_TRUE(box.contains(box.sample(rng)));
  EXPECT_FALSE(box.contains(Eigen::Vector3f(0, 0, 1.5f)));
  EXPECT_FALSE(box.contains(Eigen::Vector2f(0, 0)));
  EXPECT_TRUE(box.bounded());
  EXPECT_EQ(box.describe(), "Box(3, [-2, 1])");
}

TEST(Space, UnboundedBoxIsReported) {
  const float inf = std::numeric_limits<float>::infinity();
  const Space box = Space::box(2, -inf, inf);
  EXPECT_FALSE(box.bounded());
  Rng rng(0);
  EXPECT_TRUE(box.sample(rng).allFinite());
}

TEST(Space, DiscreteSamplesIntegers) {
  const Space space = Space::discrete(4);
  Rng rng(0);
  for (int i = 0; i < 50; ++i) {
    const Eigen::VectorXf a = space.sample(rng);
    EXPECT_TRUE(space.contains(a));
  }
  EXPECT_FALSE(space.contains(Eigen::VectorXf::Constant(1, 4.0f)));
  EXPECT_FALSE(space.contains(Eigen::VectorXf::Constant(1, 0.5f)));
  EXPECT_THROW(Space::discrete(0), Error);
}

TEST(Space, CheckActionNamesTheProblem) {
  const Space box = Space::box(2, -1.0f, 1.0f);
  try {
    check_action(box, Eigen::Vector3f(0, 0, 0), "Pendulum-v1");
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "Pendulum-v1: action has 3 components, expected 2 (Box(2, [-1, 1]))");
  }
  Eigen::Vector2f nan_action(0, std::numeric_limits<float>::quiet_NaN());
  EXPECT_THROW(check_action(box, nan_action, "x"), Error);
  EXPECT_NO_THROW(check_action(box, Eigen::Vector2f(5, 5), "x"));  // clipping is the wrapper's job
}

TEST(Info, SetOverwritesAndGets) {
  Info info;
  info.set("distance", 0.5);
  info.set("distance", 0.25);
  info.set("nan", 0);
  EXPECT_EQ(info.entries().size(), 2u);
  EXPECT_EQ(*info.get("distance"), 0.25);
  EXPECT_FALSE(info.get("cost").has_value());
}

}  // namespace
}  // namespace tendril
