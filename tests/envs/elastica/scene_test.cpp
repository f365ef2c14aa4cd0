#include <gtest/gtest.h>

#include "elastica_test_support.hpp"

namespace tendril::envs::elastica {
namespace {

TEST(ElasticaScene, DescribesTheArmTheTargetAndTheObstaclesThroughTheWrappers) {
  for (const char* id : {"Elastica/Tracking3D-v0", "Elastica/OrientedReach-v0",
                         "Elastica/StructuredObstacles-v0", "Elastica/UnstructuredObstacles-v0"}) {
    auto made = testing::make_case(id);
    ASSERT_NE(made.task, nullptr);
    made.env->reset(5);
    Action action = Action::Constant(made.env->action_space().size(), 0.8f);
    for (int i = 0; i < 20; ++i) made.env->step(action);

    Scene scene;
    ASSERT_TRUE(made.env->describe_scene(scene)) << id;  // reached through the TimeLimit
    ASSERT_EQ(scene.rods.size(), 1u);
    EXPECT_EQ(scene.rods[0].role, "arm");
    EXPECT_EQ(scene.rods[0].centreline, made.task->node_positions());
    EXPECT_EQ(scene.rods[0].radii.size(), made.task->arm().rod.n_elements());
    EXPECT_EQ(scene.rods[0].radii, made.task->arm().rod.state().radii);
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].role, "target");
    EXPECT_EQ(scene.spheres[0].centre, made.task->target_position());
    EXPECT_EQ(scene.spheres[0].radius, ElasticaArmEnv::kTargetRadius);
    ASSERT_EQ(scene.cylinders.size(), made.task->obstacles().size()) << id;
    for (size_t k = 0; k < scene.cylinders.size(); ++k) {
      EXPECT_EQ(scene.cylinders[k].start, made.task->obstacles()[k].start);
      EXPECT_EQ(scene.cylinders[k].end, made.task->obstacles()[k].end());
      EXPECT_EQ(scene.cylinders[k].radius, made.task->obstacles()[k].radius);
    }
    EXPECT_DOUBLE_EQ(scene.time, made.task->time());
    EXPECT_GT(scene.time, 0.0);
  }
}

}  // namespace
}  // namespace tendril::envs::elastica
