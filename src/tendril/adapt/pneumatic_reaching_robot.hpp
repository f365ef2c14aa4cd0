#pragma once

#include <memory>

#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/core/config.hpp"
#include "tendril/envs/pneumatic/model_dynamics.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"

namespace tendril::adapt {

// The pneumatic arm's reaching task (seed 002 §IV-A) as a ReachingRobot: the task
// (envs::pneumatic::ReachEnv) over the robot interface PneumaticArm/Robot-v0 (the twin today)
// or over the learned model (PneumaticArm/LearnedReach-v0, for the coach's trajectories).
// States are the 9 module-tip coordinates (mm, robot frame), commands the 9 normalised
// pressures; the task point is module 3's tip.
class PneumaticReachingRobot final : public ReachingRobot {
 public:
  explicit PneumaticReachingRobot(std::unique_ptr<Env> reach_env);
  // PneumaticArm/Reach-v0 or PneumaticArm/LearnedReach-v0 from its env params.
  static std::unique_ptr<PneumaticReachingRobot> on_robot(const Config& params);
  static std::unique_ptr<PneumaticReachingRobot> on_model(const Config& params);

  int state_dim() const override { return 9; }
  int command_dim() const override { return 9; }
  // tip_m1_x_mm, …, tip_m3_z_mm
  std::vector<std::string> state_names() const override;
  Eigen::VectorXd reset(std::optional<uint64_t> seed) override;
  Eigen::VectorXd step(const Eigen::VectorXd& command) override;
  const Eigen::VectorXd& command() const override { return command_; }
  const ReachStatus& status() const override { return status_; }
  Observation observation_of(const Eigen::VectorXd& state) const override;
  Eigen::VectorXd command_after(const Action& action) const override;
  Eigen::Vector3d task_point(const Eigen::VectorXd& state) const override;
  Eigen::Vector3d goal() const override;
  double success_distance() const override;

  envs::pneumatic::ReachEnv& env() { return *env_; }

 private:
  void read_status(const Info& info, double reward);

  std::unique_ptr<Env> owner_;
  envs::pneumatic::ReachEnv* env_;
  Eigen::VectorXd command_;
  ReachStatus status_;
};

// GPRCA's model F_φ: the learned model of PneumaticArm/LearnedReach-v0 (its `model` and rest
// parameters) fed the arm's measured tips (envs::pneumatic::ModelDynamics::follow).
class PneumaticHistoryModel final : public RobotHistoryModel {
 public:
  explicit PneumaticHistoryModel(const Config& learned_reach_params);

  void reset(const Eigen::VectorXd& state) override;
  Eigen::VectorXd predict(const Eigen::VectorXd& command) override;
  void follow(const Eigen::VectorXd& state) override;

 private:
  std::unique_ptr<Env> owner_;
  envs::pneumatic::ModelDynamics* model_;
};

}  // namespace tendril::adapt
