#include "tendril/envs/elastica/unstructured_obstacles.hpp"

#include <gtest/gtest.h>

#include "elastica_test_support.hpp"
#include "tendril/envs/elastica/obstacles.hpp"

namespace tendril::envs::elastica {
namespace {

using testing::make_case;

const Eigen::Vector3d kTarget(-0.8, 0.5, 0.35);

TEST(UnstructuredObstacles, NestComesFromTheObstacleSeedAndStaysFixed) {
  auto made =
      make_case<UnstructuredObstacles>("Elastica/UnstructuredObstacles-v0", "obstacle_seed: 7");
  UnstructuredObstacles& env = *made.task;
  EXPECT_EQ(env.obstacle_seed(), 7u);
  const auto expected = unstructured_nest(kTarget, 7);
  const auto check = [&] {
    ASSERT_EQ(env.obstacles().size(), 12u);
    ASSERT_NE(env.arm().contact, nullptr);
    ASSERT_EQ(env.arm().contact->cylinders().size(), 12u);
    for (std::size_t k = 0; k < 12; ++k) {
      EXPECT_EQ(env.obstacles()[k].start, expected[k].start);
      EXPECT_EQ(env.obstacles()[k].axis, expected[k].axis);
      EXPECT_EQ(env.arm().contact->cylinders()[k].start, expected[k].start);
      EXPECT_EQ(env.arm().contact->cylinders()[k].radius, 0.03);
    }
  };
  made.env->reset(1);
  check();
  made.env->reset(2);
  check();
  EXPECT_EQ(env.target_position(), kTarget);

  UnstructuredObstacles default_nest;
  EXPECT_EQ(default_nest.obstacle_seed(), 0u);
  EXPECT_NE(default_nest.obstacles()[0].start, expected[0].start);
}

TEST(UnstructuredObstacles, ObservationLayoutWithTheNest) {
  UnstructuredObstacles env(3);
  env.reset(0);
  Step step;
  for (int i = 0; i < 10; ++i) step = env.step(Action::Constant(4, 0.5f));
  const Observation& obs = step.observation;
  ASSERT_EQ(obs.size(), 220);
  testing::expect_rod_block(obs, env.arm().rod);
  EXPECT_EQ(obs.segment(37, 3), kTarget.cast<float>());
  for (int k = 0; k < 12; ++k) {
    const physics::Cylinder& cylinder = env.obstacles()[k];
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < 5; ++i) {
        EXPECT_FLOAT_EQ(obs[40 + 15 * k + 5 * c + i],
                        static_cast<float>(cylinder.start[c] + 0.25 * i * cylinder.axis[c]));
      }
    }
  }
  EXPECT_TRUE(step.info.has("contacts"));
}

// Two normal then two binormal control points at L/3 and 2L/3, each moving by at most 0.01
// per physics step (14 per action).
TEST(UnstructuredObstacles, ActuationIsTwoNormalTwoBinormalAndRateLimited) {
  UnstructuredObstacles env;
  const auto& spec = env.arm().muscles->spec();
  EXPECT_EQ(spec.control_points, 2);
  EXPECT_EQ(spec.directions, (std::array<bool, 3>{true, true, false}));
  ASSERT_EQ(spec.positions.size(), 2u);
  EXPECT_NEAR(spec.positions[0], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(spec.positions[1], 2.0 / 3.0, 1e-15);
  env.reset(0);
  env.step(Eigen::Vector4f(1.0f, -1.0f, 0.05f, 0.5f));
  const Eigen::VectorXd& current = env.arm().muscles->current();
  EXPECT_NEAR(current[0], 0.14, 1e-12);
  EXPECT_NEAR(current[1], -0.14, 1e-12);
  EXPECT_NEAR(current[2], 0.05, 1e-7);
  EXPECT_NEAR(current[3], 0.14, 1e-12);
}

}  // namespace
}  // namespace tendril::envs::elastica
