#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/pneumatic/arm_dynamics.hpp"
#include "tendril/envs/pneumatic/reach_task.hpp"
#include "tendril/envs/reach_command_task.hpp"
#include "tendril/envs/robot_history_model.hpp"

namespace tendril::envs::pneumatic {

struct PneumaticDataset;

// How observations are normalised (seed 002 §IV-A1: "normalized in the range −1 to 1 based on
// the minimum and maximum values (in individual axes in each module) taken from the dataset").
struct ReachObservationSpec {
  TipVector tip_min, tip_max;  // mm, per coordinate, from the dynamics model's data set
  // G_dist and O_dist enter as 2 d / distance_scale − 1 ([A]: the seed does not say how the
  // distances are normalised; 300 mm is about the diagonal of B's horizontal extent).
  double distance_scale = 300.0;
  // [A] variant: the 9 normalised commands a_t appended (the spec's 20-dim observation).
  bool observe_command = false;

  // Bounds from data/pneumatic_arm/twin_s0.csv, the default twin's 10-minute data set
  // (docs/results/pneumatic_arm.md gives the command that wrote it).
  static ReachObservationSpec twin_dataset();
  // Bounds from a data set's tip columns (the rest as defaults).
  static ReachObservationSpec from_dataset(const PneumaticDataset& data);
  int size() const { return observe_command ? 20 : 11; }
  void validate() const;
};

// The reaching task of seed 002 §IV-A over an arm's dynamics: PneumaticArm/Reach-v0 on the
// robot interface (the twin), and the learned-model environment with a model behind ArmDynamics.
//
//   action       9 deltas in [−max_delta, max_delta] (0.2), normalised units; the environment
//                keeps the command a ∈ [−1, 1]⁹ (a = −1 ↔ 0 bar, a = 1 ↔ 1.5 bar: p = 0.75 (a + 1))
//                and adds the delta to it, then caps it to [−1, 1] (the 1.5 bar ceiling). A delta
//                beyond the rate limit (0.15 bar = 0.2 normalised, §IV-A3) is not taken: the
//                command stays, the arm steps under it and the usual reward applies (info
//                "rate_limited" = 1). An Error for a wrong size or non-finite value.
//   observation  the 9 tip coordinates normalised per axis by ReachObservationSpec, then G_dist and
//                O_dist normalised (11 values; 20 with the command).
//   reward       evaluate_reach_step (eq. (2) with the −2 step penalty) on module 3's tip.
//   reset        the arm at rest with every chamber vented (a = −1).
// Info: "distance" (G_dist in m), "goal_distance_mm", "obstacle_distance_mm", "is_success",
// "collision", "warning", "outside_boundary", "rate_limited", "nan". Episodes are cut by the
// registry's time limit (150 steps, §IV-A3).
//
// As a ReachCommandTask (reach_env_command.cpp), for online adaptation: states are the 9 tip
// coordinates (mm, robot frame), commands the 9 normalised pressures, the task point module 3's
// tip; in a learned model, the model fed the arm's measured tips (model_history.hpp).
class ReachEnv : public Env, public ReachCommandTask {
 public:
  struct Setup {
    std::string id;
    ReachTaskSpec task;
    ReachObservationSpec observation = ReachObservationSpec::twin_dataset();
    double max_delta = 0.2;   // action bound, normalised
    double rate_limit = 0.2;  // largest delta taken, normalised (0.15 bar)
  };

  // Reads the task and observation parameters shared by every dynamics source:
  //   task: main | G1 | G2 | G3          goal_mm: [x, y, z]
  //   obstacle_min_mm, obstacle_max_mm:  [x, y, z]      boundary: paper | relaxed
  //   boundary_min_mm, boundary_max_mm:  [x, y, z]      obstacle_distance: box | plane
  //   success_distance_mm: 5             terminate_outside_boundary: true
  //   observe_command: false             rate_limit_bar: 0.15
  //   normalization: {dataset: FILE, tip_min_mm: [9], tip_max_mm: [9], distance_scale_mm: 300}
  //     (bounds from the data set FILE, else the default twin's; tip_min_mm/tip_max_mm override)
  static Setup setup_from(const Config& params, std::string id);
  // PneumaticArm/Reach-v0: the task on PneumaticArm/Robot-v0 built from params.robot.
  static std::unique_ptr<Env> create_on_robot(const Config& params);
  static constexpr const char* kRobotId = "PneumaticArm/Reach-v0";
  // PneumaticArm/LearnedReach-v0: the task on a learned model of the arm (ModelDynamics), for
  // training (seed 002 §IV-A). Besides setup_from's parameters:
  //   model: FILE_OR_RUN   a model file or a `tendril model fit` run (9 tips, 9 pressures),
  //                        opened through install_dynamics_model_loader; without it
  //                        LinearArmModel, a torch-free stand-in (not the arm)
  //   rest_mm: [9]         the tips with every chamber vented, where episodes start; else
  //   rest_from: FILE      the first row of a pneumatic data set (tendril data collect) (the
  //                        arm at rest before the signal's first command); else the stand-in's
  //                        rest
  static std::unique_ptr<Env> create_on_model(const Config& params);
  // The two environments in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription robot_description();
  static EnvDescription model_description();
  static constexpr const char* kModelId = "PneumaticArm/LearnedReach-v0";
  static constexpr int64_t kEpisodeSteps = 150;

  // `history`: the dynamics as a model fed measured history, where they are a learned model.
  ReachEnv(Setup setup, std::unique_ptr<ArmDynamics> dynamics,
           std::unique_ptr<RobotHistoryModel> history = nullptr);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // A step with an absolute command (normalised, a ∈ [−1, 1]⁹) instead of a delta, for
  // controllers that set pressures themselves (BOAC's student, seed 002 §IV-B): the command is
  // capped to [−1, 1], and a change from the held command beyond the rate limit is scaled down
  // as a whole to it (the robot never gets a larger jump, in the direction asked; info
  // "rate_limited" = 1 when it was scaled). Then as step().
  Step step_command(const ChamberVector& command);
  // The observation the policy would receive if the tips were `tips_mm` (with the distances
  // computed from them and the held command): GPRCA's compensated observation s = x + c.
  Observation observation_of(const TipVector& tips_mm) const;
  bool supports_snapshots() const override { return dynamics_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The arm (from the dynamics), the goal, the plate and the boundary box.
  bool describe_scene(Scene& scene) const override;

  static double pressure_of(double command) { return 0.75 * (command + 1.0); }
  const ChamberVector& command() const { return command_; }  // normalised
  const TipVector& tips() const { return tips_; }            // mm
  const ReachTaskSpec& task() const { return setup_.task; }
  const ReachObservationSpec& observation_spec() const { return setup_.observation; }
  double rate_limit() const { return setup_.rate_limit; }
  ArmDynamics& dynamics() { return *dynamics_; }

  // ReachCommandTask.
  int state_dim() const override { return 9; }
  int command_dim() const override { return 9; }
  // tip_m1_x_mm, …, tip_m3_z_mm
  std::vector<std::string> state_names() const override;
  ReachStatus reset_reach(std::optional<uint64_t> seed) override;
  // step_command's rate limit and cap; Error for a non-finite arm.
  ReachStatus hold_command(const Eigen::VectorXd& command) override;
  Eigen::VectorXd measured_state() const override { return tips_; }
  Eigen::VectorXd held_command() const override { return command_; }
  Observation observation_at(const Eigen::VectorXd& state) const override;
  // As step(): the delta added and capped, or not taken beyond the rate limit.
  Eigen::VectorXd command_after(const Action& action) const override;
  Eigen::Vector3d task_point(const Eigen::VectorXd& state) const override;
  Eigen::Vector3d goal() const override { return setup_.task.goal; }
  double success_distance() const override { return setup_.task.success_distance; }
  RobotHistoryModel* history_model() override { return history_.get(); }

 private:
  Observation observe(const TipVector& tips, double goal_distance, double obstacle_distance) const;
  // Holds `command` (already capped) for one period and scores the step.
  Step advance(const ChamberVector& command, bool rate_limited);

  Setup setup_;
  std::unique_ptr<ArmDynamics> dynamics_;
  std::unique_ptr<RobotHistoryModel> history_;  // refers to dynamics_: destroyed before it
  Space observation_space_, action_space_;
  ChamberVector command_ = ChamberVector::Constant(-1.0);
  TipVector tips_ = TipVector::Zero();
  Observation last_observation_;
  Info info_;
};

}  // namespace tendril::envs::pneumatic
