#include "tendril/envs/elastica/structured_obstacles.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "elastica_test_support.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/elastica/intersection.hpp"
#include "tendril/envs/elastica/obstacles.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {
namespace {

using testing::make_case;

// The 5 points along an obstacle's axis, coordinate-major, as the observation holds them.
void expect_obstacle_block(const Observation& obs, int offset, const physics::Cylinder& cylinder) {
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 5; ++i) {
      const double expected = cylinder.start[c] + 0.25 * i * cylinder.length * cylinder.axis[c];
      ASSERT_FLOAT_EQ(obs[offset + 5 * c + i], static_cast<float>(expected))
          << "offset " << offset << ", coordinate " << c << ", point " << i;
    }
  }
}

TEST(StructuredObstacles, ObservationLayoutWithTheWall) {
  StructuredObstacles env;
  const Observation obs = env.reset(0);
  ASSERT_EQ(obs.size(), 160);
  testing::expect_rod_block(obs, env.arm().rod);
  EXPECT_EQ(obs.segment(37, 3), Eigen::Vector3f(-0.8f, 0.5f, 0.15f));
  const auto wall = structured_wall();
  ASSERT_EQ(env.obstacles().size(), 8u);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(env.obstacles()[k].start, wall[k].start);
    expect_obstacle_block(obs, 40 + 15 * k, wall[k]);
  }
  // E.g. the first post's axis (−0.6, y, 0.12), y = 0, 0.25, …, 1.
  EXPECT_EQ(obs.segment(40, 15), (Eigen::VectorXf(15) << -0.6f, -0.6f, -0.6f, -0.6f, -0.6f, 0.0f,
                                  0.25f, 0.5f, 0.75f, 1.0f, 0.12f, 0.12f, 0.12f, 0.12f, 0.12f)
                                     .finished());
  // The target is fixed whatever the seed.
  env.reset(99);
  EXPECT_EQ(env.target_position(), Eigen::Vector3d(-0.8, 0.5, 0.15));
}

TEST(StructuredObstacles, RewardTableAroundTheTip) {
  StructuredObstacles env;
  env.reset(0);
  const Eigen::Vector3d tip = env.arm().rod.tip_position();
  for (const double offset : {0.04, 0.08, 0.3}) {
    env.set_target(tip + Eigen::Vector3d(-offset, 0.0, 0.0));
    const Step step = env.step(Action::Zero(2));
    const double d = *step.info.get("distance");
    EXPECT_NEAR(d, offset, 1e-9);
    EXPECT_DOUBLE_EQ(step.reward, reach_reward(d));
    EXPECT_NEAR(step.reward, -d * d + (offset < 0.05 ? 2.0 : offset < 0.1 ? 0.5 : 0.0), 1e-12);
    EXPECT_EQ(*step.info.get("is_success"), offset < 0.05 ? 1.0 : 0.0);
    EXPECT_EQ(*step.info.get("contacts"), 0.0);
  }
}

TEST(StructuredObstacles, ParametersSelectTheSeedVariants) {
  auto four =
      make_case<StructuredObstacles>("Elastica/StructuredObstacles-v0", "control_points: 4");
  EXPECT_EQ(four.env->action_space().size(), 4);
  EXPECT_EQ(four.task->arm().muscles->spec().positions, (std::vector<double>{0.2, 0.4, 0.6, 0.8}));

  auto seed = make_case<StructuredObstacles>("Elastica/StructuredObstacles-v0",
                                             "control_point_positions: [0.4, 0.9]");
  EXPECT_EQ(seed.env->action_space().size(), 2);
  EXPECT_EQ(seed.task->arm().muscles->spec().positions, (std::vector<double>{0.4, 0.9}));
  EXPECT_EQ(seed.task->arm().muscles->spec().directions, (std::array<bool, 3>{true, false, false}));
  EXPECT_EQ(seed.task->arm().muscles->spec().max_change_per_step, 0.01);
  EXPECT_NE(seed.task->arm().contact, nullptr);

  const auto fails = [](const std::string& yaml) {
    EXPECT_THROW(make("Elastica/StructuredObstacles-v0", Config::parse(yaml)), Error) << yaml;
  };
  fails("control_points: 0");
  fails("control_point_positions: [0.9, 0.4]");
  fails("control_point_positions: [0.4, 1.0]");
  fails("control_points: 4\ncontrol_point_positions: [0.4, 0.9]");
  fails("obstacle_mode: avoid");
  fails("obstacle_mode: penalty\npenalty_weight: -1");
}

// Bending with both control points at +0.6 pushes the arm into the wall (as in the rod's
// allocation test): contact mode reports element–cylinder contacts and no penalty, and the
// contact forces keep the arm out of the wall. The soft wall (k = 8·10⁴ N/m) lets the arm, which
// whips into the wall at first, sink in briefly — measured: up to 3–4 cm around step 100 — but
// its centreline always stays more than a centimetre outside every cylinder (capsules of radius
// 1 cm around the elements never intersect one), and once it has settled (from step 150) no
// element is a centimetre deep. Without contact forces (the penalty variant below) the arm's
// centreline sweeps right through the cylinders.
constexpr double kSettledRadius = StructuredObstacles::kArmRadius - 0.01;  // m
constexpr double kCentrelineClearance = 0.01;                              // m

TEST(StructuredObstacles, ContactModeReportsContactsAndKeepsTheArmOutOfTheWall) {
  StructuredObstacles env;
  env.reset(0);
  double most_contacts = 0.0;
  for (int i = 0; i < 350; ++i) {
    const Step step = env.step(Action::Constant(2, 0.6f));
    ASSERT_FALSE(step.terminated) << i;
    most_contacts = std::max(most_contacts, *step.info.get("contacts"));
    ASSERT_EQ(*step.info.get("penalty"), 0.0);
    ASSERT_EQ(intersecting_elements(env.arm().rod, kCentrelineClearance, env.obstacles()), 0)
        << "step " << i << ": the arm passes into a cylinder";
    if (i >= 150) {
      ASSERT_EQ(intersecting_elements(env.arm().rod, kSettledRadius, env.obstacles()), 0)
          << "step " << i << ": the settled arm is a centimetre deep in the wall";
    }
  }
  EXPECT_GT(most_contacts, 0.0);
}

// The penalty variant (seed 000): no contact forces, R = reach_reward(d) − φ·(intersecting
// elements / 50).
TEST(StructuredObstacles, PenaltyModePaysPhiTimesTheIntersectingFraction) {
  auto made = make_case<StructuredObstacles>("Elastica/StructuredObstacles-v0",
                                             "obstacle_mode: penalty\npenalty_weight: 100");
  StructuredObstacles& env = *made.task;
  EXPECT_EQ(env.arm().contact, nullptr);
  EXPECT_EQ(env.obstacles().size(), 8u);
  EXPECT_EQ(made.env->reset(0).size(), 160);
  int penalized_steps = 0, centreline_inside = 0;
  for (int i = 0; i < 350; ++i) {
    // Without the wall to stop it, the strongly bent arm eventually goes unstable.
    const Step step = made.env->step(Action::Constant(2, 0.6f));
    if (step.terminated) break;
    const double inside = *step.info.get("contacts");
    ASSERT_EQ(inside, intersecting_elements(env.arm().rod, 0.05, env.obstacles()));
    ASSERT_EQ(*step.info.get("penalty"), 100.0 * inside / 50.0);
    ASSERT_DOUBLE_EQ(step.reward, reach_reward(*step.info.get("distance")) - 100.0 * inside / 50.0);
    if (inside > 0) ++penalized_steps;
    centreline_inside =
        std::max(centreline_inside, intersecting_elements(env.arm().rod, 0.0, env.obstacles()));
  }
  EXPECT_GT(penalized_steps, 0) << "the arm should have swept into the wall";
  EXPECT_GT(centreline_inside, 0) << "without contact forces the arm should pass into the wall";
}

}  // namespace
}  // namespace tendril::envs::elastica
