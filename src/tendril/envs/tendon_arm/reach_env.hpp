#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/tendon_arm/plant.hpp"

namespace tendril::envs::tendon_arm {

// The reach task of the tendon arm, on a plant: TendonArm/Reach-v0 on the robot
// (TendonArm/Robot-v0), TendonArm/LearnedReach-v0 on a learned model of it.
//
//   reset        draws goal tensions from the reset's stream — each U[0, max], less their
//                smallest, so one tendon is slack and the bend covers every direction — holds
//                them on the plant for `goal_settle_steps` (15 periods, 1.5 s: the robot settles
//                within about 1 s), takes the tip there as the goal, and resets the plant: every
//                goal is reachable by the very plant the task runs on, robot or model.
//   action       the tendon tensions, N, Box [0, max_tension] (the robot's own action).
//   observation  in arm lengths L (0.30 m): the tip (3, lab frame), the goal less the tip (3),
//                then the tensions held, over max_tension (one per tendon).
//   reward       −|goal − tip| / L every step (0 at the goal; about −0.3 for the farthest goals).
//   episode      50 steps (5 s) by the registry's time limit; never terminated but by a
//                non-finite plant (info "nan" = 1).
// Info: "distance" (m), "is_success" (distance ≤ success_radius_m, 10 mm), "nan".
class ReachEnv : public Env {
 public:
  struct Setup {
    std::string id;
    double success_radius = 0.01;  // m
    int goal_settle_steps = 15;
    double length = 0.30;  // m, the observation's and reward's scale
  };

  static constexpr const char* kRobotId = "TendonArm/Reach-v0";
  static constexpr const char* kModelId = "TendonArm/LearnedReach-v0";
  static constexpr int64_t kEpisodeSteps = 50;

  // TendonArm/Reach-v0: the task on TendonArm/Robot-v0 built from `robot:` (ArmSpec's keys).
  // Task keys: success_radius_m, goal_settle_steps.
  static std::unique_ptr<Env> create_on_robot(const Config& params);
  // TendonArm/LearnedReach-v0: the task on a learned model of the arm. Besides the task keys:
  //   model: FILE_OR_RUN     required: a model file or a `tendril model fit` run mapping the tip
  //                          (m) and the tensions (N) to the tip (opened through the installed
  //                          model loader), or `constant_curvature` (ConstantCurvatureModel, a
  //                          torch-free stand-in, not the arm)
  //   rest_m: [x, y, z]      the tip hanging at rest (default: the default twin's)
  //   max_tension_n: 6       the action bound (the robot's)
  //   length_m: 0.30         the scale of observations and reward (the robot's length)
  static std::unique_ptr<Env> create_on_model(const Config& params);
  // The two environments in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription robot_description();
  static EnvDescription model_description();

  ReachEnv(Setup setup, std::unique_ptr<Plant> plant);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return plant_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The plant's scene, and the goal.
  bool describe_scene(Scene& scene) const override;

  const Eigen::Vector3d& goal() const { return goal_; }
  // The tensions the goal was made with: held from a reset, they bring the plant to the goal.
  const Eigen::VectorXd& goal_tensions() const { return goal_tensions_; }
  const Eigen::Vector3d& tip() const { return tip_; }
  Plant& plant() { return *plant_; }

 private:
  Observation observe() const;

  Setup setup_;
  std::unique_ptr<Plant> plant_;
  Space observation_space_, action_space_;
  Rng rng_;
  Eigen::Vector3d goal_ = Eigen::Vector3d::Zero(), tip_ = Eigen::Vector3d::Zero();
  Eigen::VectorXd tensions_, goal_tensions_;
  Info info_;
};

}  // namespace tendril::envs::tendon_arm
