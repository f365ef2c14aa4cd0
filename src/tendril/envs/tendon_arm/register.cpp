#include "tendril/envs/tendon_arm/register.hpp"

#include "tendril/envs/tendon_arm/reach_env.hpp"
#include "tendril/envs/tendon_arm/robot_env.hpp"

namespace tendril::envs::tendon_arm {

void register_envs(Registry& registry) {
  // The robot: tendon tensions in, tip position and tendon displacements out (its twin behind).
  registry.add(
      {RobotEnv::kId, &RobotEnv::create, RobotEnv::kTrialSteps,
       "tendon-driven continuum arm twin: 3 tensions in, tip and tendon travel out (robot)",
       &RobotEnv::description});
  // Its reach task on the robot, 50 steps of 0.1 s.
  registry.add({ReachEnv::kRobotId, &ReachEnv::create_on_robot, ReachEnv::kEpisodeSteps,
                "tendon arm's tip reaches a random reachable goal (task on the robot twin)",
                &ReachEnv::robot_description});
  // The same task inside a learned model of the arm; `model:` is required (constant_curvature
  // names the torch-free stand-in, which the tests that make every id use).
  registry.add({ReachEnv::kModelId, &ReachEnv::create_on_model, ReachEnv::kEpisodeSteps,
                "tendon arm's tip reaches a random reachable goal (task in a learned model)",
                &ReachEnv::model_description, nullptr, "model: constant_curvature"});
}

}  // namespace tendril::envs::tendon_arm
