#include "tendril/envs/builtin_envs.hpp"

#include "tendril/envs/beam/beam_tasks.hpp"
#include "tendril/envs/classic_control/cart_pole.hpp"
#include "tendril/envs/classic_control/mountain_car_continuous.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/elastica/oriented_reach.hpp"
#include "tendril/envs/elastica/pooled_arm_vec_env.hpp"
#include "tendril/envs/elastica/structured_obstacles.hpp"
#include "tendril/envs/elastica/tracking_3d.hpp"
#include "tendril/envs/elastica/unstructured_obstacles.hpp"
#include "tendril/envs/identity/identity.hpp"
#include "tendril/envs/identity/identity_box.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"
#include "tendril/envs/safe_control/double_integrator.hpp"
#include "tendril/envs/safe_control/dubins_car.hpp"
#include "tendril/envs/sma_limb/learned_reach_env.hpp"
#include "tendril/envs/sma_limb/learned_reach_vec_env.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/tendon_arm/register.hpp"
#include "tendril/envs/ur5/ur5_reach.hpp"

namespace tendril::envs {

void register_builtin_envs(Registry& registry) {
  // Gymnasium's classic-control reference tasks, with Gymnasium's registered time limits.
  registry.add({"Pendulum-v1", &Pendulum::create, 200, "swing up a pendulum (Gymnasium)",
                &Pendulum::description});
  registry.add({"CartPole-v1", &CartPole::create, 500, "balance a pole on a cart (Gymnasium)",
                &CartPole::description});
  registry.add({"MountainCarContinuous-v0", &MountainCarContinuous::create, 999,
                "drive an under-powered car up a hill (Gymnasium)",
                &MountainCarContinuous::description});
  // Stable-Baselines3's identity sanity checks, episodes of 100 steps.
  registry.add({"Identity-v0", &Identity::create, 100,
                "repeat a one-hot state as a discrete action", &Identity::description});
  registry.add({"IdentityBox-v0", &IdentityBox::create, 100, "repeat a scalar state within eps",
                &IdentityBox::description});
  // The Elastica soft-arm control cases 1–4 (seed 000, SPEC M2); limits are 10 s, 2 s, 5 s, 5 s
  // of 1.4 ms RL steps. With lockstep_rods, make_vector advances case 1's rods in one RodPool.
  registry.add({"Elastica/Tracking3D-v0", &elastica::Tracking3D::create,
                elastica::Tracking3D::kEpisodeSteps, "soft arm tracks a moving target (case 1)",
                &elastica::Tracking3D::description, &elastica::PooledArmVecEnv::create});
  registry.add({"Elastica/OrientedReach-v0", &elastica::OrientedReach::create,
                elastica::OrientedReach::kEpisodeSteps,
                "soft arm reaches a target position and orientation (case 2)",
                &elastica::OrientedReach::description});
  registry.add({"Elastica/StructuredObstacles-v0", &elastica::StructuredObstacles::create,
                elastica::StructuredObstacles::kEpisodeSteps,
                "soft arm reaches through a gap in a wall of cylinders (case 3)",
                &elastica::StructuredObstacles::description});
  registry.add({"Elastica/UnstructuredObstacles-v0", &elastica::UnstructuredObstacles::create,
                elastica::UnstructuredObstacles::kEpisodeSteps,
                "soft arm reaches through a random nest of cylinders (case 4)",
                &elastica::UnstructuredObstacles::description});
  // The three-module pneumatic arm of seed 002 (SPEC M9): the robot interface with its twin
  // behind; trials of the paper's 150 control steps (15 s).
  registry.add({pneumatic::RobotEnv::kId, &pneumatic::RobotEnv::create,
                pneumatic::RobotEnv::kTrialSteps,
                "pneumatic 3-module arm twin: 9 pressures in, 3 tip positions out (robot)",
                &pneumatic::RobotEnv::description});
  // Its reaching task past a plate (seed 002 §IV-A, eq. (2)) on that robot, 150 steps of 0.1 s.
  registry.add({pneumatic::ReachEnv::kRobotId, &pneumatic::ReachEnv::create_on_robot,
                pneumatic::ReachEnv::kEpisodeSteps,
                "pneumatic arm reaches a goal behind a plate (task on the robot twin)",
                &pneumatic::ReachEnv::robot_description});
  // The same task inside a learned model of the arm, where the seed trains its policy.
  registry.add({pneumatic::ReachEnv::kModelId, &pneumatic::ReachEnv::create_on_model,
                pneumatic::ReachEnv::kEpisodeSteps,
                "pneumatic arm reaches a goal behind a plate (task in a learned model)",
                &pneumatic::ReachEnv::model_description});
  // The SMA limb of seed 001 as its software sees it (throttles in, bend readings out); no time
  // limit: data collection runs for hours, tasks bring their own.
  // It never runs on a default calibration (sma_limb_env.hpp); listings show it uncalibrated.
  registry.add({sma_limb::SmaLimbEnv::kId, &sma_limb::SmaLimbEnv::create, std::nullopt,
                "SMA-actuated silicone limb: throttles in, bend-sensor readings out (twin)",
                &sma_limb::SmaLimbEnv::description, nullptr, "calibration: none"});
  // The safety-filter benchmarks of seed 001 §6.4.1 (SPEC M8); each truncates at its own
  // configured horizon T, which its observation's time entry t/T refers to.
  registry.add({safe_control::DoubleIntegrator::kId, &safe_control::DoubleIntegrator::create,
                std::nullopt, "double integrator kept in |x| < 2 m, |v| < 3 m/s (safety filter)",
                &safe_control::DoubleIntegrator::description});
  registry.add({safe_control::DubinsCar::kId, &safe_control::DubinsCar::create, std::nullopt,
                "Dubins car to a goal past a keep-out disc (safety filter)",
                &safe_control::DubinsCar::description});
  // Its reaching task inside a learned model of the limb (seed 001 §5.1.1), 250 steps.
  // N of them step through one batched model call (make_vector, used by training).
  registry.add({sma_limb::LearnedReachEnv::kId, &sma_limb::LearnedReachEnv::create,
                sma_limb::LearnedReachEnv::kEpisodeSteps,
                "SMA limb reaches a goal angle inside a learned model of the limb",
                &sma_limb::LearnedReachEnv::description, &sma_limb::LearnedReachVecEnv::create});
  // Its safety agent's environment inside a learned model of the limb (seed 001 §6.5.2),
  // truncated at its own configured horizon.
  registry.add({sma_limb::LearnedSafetyEnv::kId, &sma_limb::LearnedSafetyEnv::create, std::nullopt,
                "SMA limb kept within a 30° bend inside a learned model (safety filter)",
                &sma_limb::LearnedSafetyEnv::description});
  // Seed 004 (SPEC M10): the UR5 in MuJoCo, 1000 steps of 20 ms.
  registry.add({ur5::Ur5Reach::kId, &ur5::Ur5Reach::create, ur5::Ur5Reach::kEpisodeSteps,
                "UR5 arm reaches past an obstacle box, tool down (MuJoCo)",
                &ur5::Ur5Reach::description});
  // Seed 003's mass-spring beam under five torques (SPEC M4): 10 s of 50 ms steps, 13 s for
  // the ellipse.
  registry.add({"Beam/ArcFollow-v0", &beam::make_arc_follow, beam::kArcEpisodeSteps,
                "mass-spring beam's tip follows arcs (task 1)", &beam::arc_follow_description});
  registry.add({"Beam/TrajectoryFollow-v0", &beam::make_trajectory_follow, beam::kArcEpisodeSteps,
                "mass-spring beam's tip follows arcs at a varying speed (task 2)",
                &beam::trajectory_follow_description});
  registry.add({"Beam/EnergyAwareFollow-v0", &beam::make_energy_aware_follow,
                beam::kArcEpisodeSteps,
                "mass-spring beam follows arcs and saves torque work (task 3)",
                &beam::energy_aware_follow_description});
  registry.add({"Beam/EllipseFollow-v0", &beam::make_ellipse_follow, beam::kEllipseEpisodeSteps,
                "mass-spring beam's tip follows an ellipse, with levels (task 4)",
                &beam::ellipse_follow_description});
  // A tendon-driven continuum arm: its robot, its reach task on the robot and on a learned model.
  tendon_arm::register_envs(registry);
}

}  // namespace tendril::envs
