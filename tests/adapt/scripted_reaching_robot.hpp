#pragma once

// A scripted reaching robot for BOAC and GPRCA: one module (a 3-D task point, mm) driven by a
// 3-D command a ∈ [−1, 1]³ toward a linear map's point at first order,
// x_{t+1} = x_t + α (rest + bias + B a_t − x_t) (α = 1: a new command settles in one step), the
// command's change limited to ±0.2 per step, and a goal. Its "learned model" is the same map
// without the bias, fed the robot's measured state; its policy a proportional controller with the
// model's feedforward.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::adapt::testing {

struct LinearArm {
  Eigen::Vector3d rest{0.0, 0.0, -600.0};
  Eigen::Matrix3d mixing = (Eigen::Matrix3d() << 60, 10, 0, -5, 50, 8, 0, 4, 25).finished();
  Eigen::Vector3d at(const Eigen::Vector3d& command) const { return rest + mixing * command; }
};

class ScriptedReachingRobot final : public ReachingRobot {
 public:
  ScriptedReachingRobot(LinearArm arm, Eigen::Vector3d bias, Eigen::Vector3d goal,
                        double rest_jitter = 0.0, double lag = 1.0)
      : arm_(arm), bias_(bias), goal_(goal), jitter_(rest_jitter), lag_(lag) {}

  int state_dim() const override { return 3; }
  int command_dim() const override { return 3; }
  std::vector<std::string> state_names() const override { return {"x_mm", "y_mm", "z_mm"}; }

  Eigen::VectorXd reset(std::optional<uint64_t> seed) override {
    if (seed) rng_ = Rng(*seed);
    command_ = Eigen::VectorXd::Constant(3, -1.0);
    offset_.setZero();
    if (jitter_ > 0.0) {
      for (int i = 0; i < 3; ++i) offset_[i] = jitter_ * rng_.normal();
    }
    state_ = arm_.at(command_) + bias_ + offset_;
    status_ = ReachStatus{};
    status_.goal_distance = (state_ - goal_).norm();
    status_.obstacle_distance = 1e3;
    ++resets_;
    return state_;
  }

  Eigen::VectorXd step(const Eigen::VectorXd& command) override {
    const Eigen::VectorXd change = (command - command_).cwiseMax(-0.2).cwiseMin(0.2);
    command_ = (command_ + change).cwiseMax(-1.0).cwiseMin(1.0);
    state_ += lag_ * (arm_.at(command_) + bias_ + offset_ - state_);
    status_.goal_distance = (state_ - goal_).norm();
    status_.success = status_.goal_distance <= success_distance();
    status_.reward = -2.0 - (status_.success ? 0.0 : status_.goal_distance);
    ++steps_;
    return state_;
  }

  const Eigen::VectorXd& command() const override { return command_; }
  const ReachStatus& status() const override { return status_; }

  // [x (3), command (3)]
  Observation observation_of(const Eigen::VectorXd& state) const override {
    Observation observation(6);
    observation << state.cast<float>(), command_.cast<float>();
    return observation;
  }
  Eigen::VectorXd command_after(const Action& action) const override {
    return (command_ + action.cast<double>().cwiseMax(-0.2).cwiseMin(0.2))
        .cwiseMax(-1.0)
        .cwiseMin(1.0);
  }
  Eigen::Vector3d task_point(const Eigen::VectorXd& state) const override { return state; }
  Eigen::Vector3d goal() const override { return goal_; }
  double success_distance() const override { return 5.98; }

  int resets() const { return resets_; }
  int steps() const { return steps_; }

 private:
  LinearArm arm_;
  Eigen::Vector3d bias_, goal_, offset_ = Eigen::Vector3d::Zero();
  double jitter_, lag_;
  Rng rng_{0};
  Eigen::VectorXd command_ = Eigen::VectorXd::Constant(3, -1.0);
  Eigen::VectorXd state_ = Eigen::VectorXd::Zero(3);
  ReachStatus status_;
  int resets_ = 0, steps_ = 0;
};

// The robot's dynamics without its bias, fed the measured state:
// x̂_{t+1} = x_t + α (rest + B a_t − x_t).
class ScriptedHistoryModel final : public RobotHistoryModel {
 public:
  explicit ScriptedHistoryModel(LinearArm arm, double lag = 1.0) : arm_(arm), lag_(lag) {}
  void reset(const Eigen::VectorXd& state) override {
    state_ = state;
    ++resets_;
  }
  Eigen::VectorXd predict(const Eigen::VectorXd& command) override {
    return state_ + lag_ * (arm_.at(command) - state_);
  }
  void follow(const Eigen::VectorXd& state) override {
    state_ = state;
    ++follows_;
  }
  int resets() const { return resets_; }
  int follows() const { return follows_; }

 private:
  LinearArm arm_;
  double lag_;
  Eigen::Vector3d state_ = Eigen::Vector3d::Zero();
  int resets_ = 0, follows_ = 0;
};

// π_θ: the model's static inverse plus proportional feedback on the observed position, as a
// delta toward that command: a = clip(B⁻¹(g − rest) + k B⁻¹(g − x) − a_held, ±0.2). On a robot
// whose map is the model's plus a bias b it settles at g + b / (1 + k).
class ProportionalPolicy final : public rl::Policy {
 public:
  ProportionalPolicy(LinearArm model, Eigen::Vector3d goal, double gain)
      : rl::Policy(Space::box(6, -1e4f, 1e4f), Space::box(3, -0.2f, 0.2f)),
        model_(model),
        goal_(goal),
        gain_(gain) {}
  std::string kind() const override { return "scripted"; }

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool, Rng&,
                   Eigen::MatrixXf& actions) const override {
    actions.resize(3, observations.cols());
    const Eigen::Matrix3d inverse = model_.mixing.inverse();
    for (Eigen::Index i = 0; i < observations.cols(); ++i) {
      const Eigen::Vector3d state = observations.col(i).head<3>().cast<double>();
      const Eigen::Vector3d held = observations.col(i).tail<3>().cast<double>();
      const Eigen::Vector3d target =
          inverse * (goal_ - model_.rest) + gain_ * inverse * (goal_ - state);
      actions.col(i) =
          (target.cwiseMax(-1.0).cwiseMin(1.0) - held).cwiseMax(-0.2).cwiseMin(0.2).cast<float>();
    }
  }
  void write(ArchiveWriter&) const override {
    throw Error("a scripted policy has no file", "ProportionalPolicy");
  }

 private:
  LinearArm model_;
  Eigen::Vector3d goal_;
  double gain_;
};

}  // namespace tendril::adapt::testing
