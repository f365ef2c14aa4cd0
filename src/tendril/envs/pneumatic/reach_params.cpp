// ReachEnv's parameters from an experiment's env.params, PneumaticArm/Reach-v0 and
// PneumaticArm/LearnedReach-v0.
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/linear_arm_model.hpp"
#include "tendril/envs/pneumatic/model_dynamics.hpp"
#include "tendril/envs/pneumatic/model_history.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/pneumatic/robot_dynamics.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"

namespace tendril::envs::pneumatic {

namespace {

template <int N>
Eigen::Matrix<double, N, 1> vector_of(const Config& config, const std::string& key,
                                      const Eigen::Matrix<double, N, 1>& fallback) {
  if (!config.has(key)) return fallback;
  const std::vector<double> values = config.get<std::vector<double>>(key);
  if (static_cast<int>(values.size()) != N) {
    throw Error("needs " + std::to_string(N) + " numbers, got " + std::to_string(values.size()),
                key_where(config, key));
  }
  Eigen::Matrix<double, N, 1> result;
  for (int i = 0; i < N; ++i) {
    if (!std::isfinite(values[i])) throw Error("must be finite", key_where(config, key));
    result[i] = values[i];
  }
  return result;
}

Eigen::AlignedBox3d box_of(const Config& config, const std::string& min_key,
                           const std::string& max_key, const Eigen::AlignedBox3d& fallback) {
  const Eigen::AlignedBox3d box(vector_of<3>(config, min_key, fallback.min()),
                                vector_of<3>(config, max_key, fallback.max()));
  if (!(box.max().array() > box.min().array()).all()) {
    throw Error("needs max > min on every axis", key_where(config, max_key));
  }
  return box;
}

}  // namespace

ReachEnv::Setup ReachEnv::setup_from(const Config& params, std::string id) {
  Setup setup;
  setup.id = std::move(id);
  ReachTaskSpec& task = setup.task;
  task =
      ReachTaskSpec::preset(params.get_or<std::string>("task", "main"), key_where(params, "task"));
  task.goal = vector_of<3>(params, "goal_mm", task.goal);
  task.obstacle = box_of(params, "obstacle_min_mm", "obstacle_max_mm", task.obstacle);
  const std::string boundary = params.get_or<std::string>("boundary", "paper");
  if (boundary == "relaxed") {
    task.boundary = ReachTaskSpec::relaxed_boundary();
  } else if (boundary != "paper") {
    throw Error("must be paper or relaxed, got '" + boundary + "'", key_where(params, "boundary"));
  }
  task.boundary = box_of(params, "boundary_min_mm", "boundary_max_mm", task.boundary);
  const std::string distance = params.get_or<std::string>("obstacle_distance", "box");
  if (distance == "plane") {
    task.obstacle_distance = ReachTaskSpec::ObstacleDistance::kPlane;
  } else if (distance != "box") {
    throw Error("must be box or plane, got '" + distance + "'",
                key_where(params, "obstacle_distance"));
  }
  task.success_distance = params.get_or<double>("success_distance_mm", task.success_distance);
  task.terminate_outside_boundary =
      params.get_or<bool>("terminate_outside_boundary", task.terminate_outside_boundary);
  try {
    task.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": " + params.path());
  }

  const double rate_limit_bar = params.get_or<double>("rate_limit_bar", 0.15);
  if (!(std::isfinite(rate_limit_bar) && rate_limit_bar > 0.0)) {
    throw Error("must be positive", key_where(params, "rate_limit_bar"));
  }
  setup.rate_limit = rate_limit_bar / 0.75;  // bar → normalised command units

  ReachObservationSpec& observation = setup.observation;
  observation.observe_command = params.get_or<bool>("observe_command", false);
  const Config normalization = params.child("normalization");
  if (normalization.has("dataset")) {
    const ReachObservationSpec bounds = ReachObservationSpec::from_dataset(
        read_pneumatic_dataset(normalization.get<std::string>("dataset")));
    observation.tip_min = bounds.tip_min;
    observation.tip_max = bounds.tip_max;
  }
  observation.tip_min = vector_of<9>(normalization, "tip_min_mm", observation.tip_min);
  observation.tip_max = vector_of<9>(normalization, "tip_max_mm", observation.tip_max);
  observation.distance_scale =
      normalization.get_or<double>("distance_scale_mm", observation.distance_scale);
  try {
    observation.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), normalization.source() + ": " + normalization.path());
  }
  return setup;
}

std::unique_ptr<Env> ReachEnv::create_on_robot(const Config& params) {
  Setup setup = setup_from(params, kRobotId);
  auto dynamics = std::make_unique<RobotDynamics>(RobotEnv::create(params.child("robot")));
  return std::make_unique<ReachEnv>(std::move(setup), std::move(dynamics));
}

std::unique_ptr<Env> ReachEnv::create_on_model(const Config& params) {
  Setup setup = setup_from(params, kModelId);
  std::shared_ptr<DynamicsModel> model;
  if (params.has("model")) {
    model = load_dynamics_model(params.get<std::string>("model"), kModelId);
  } else {
    model = std::make_shared<LinearArmModel>();
  }
  TipVector rest = LinearArmModel::rest();
  if (params.has("rest_mm")) {
    rest = vector_of<9>(params, "rest_mm", rest);
  } else if (params.has("rest_from")) {
    const std::string file = params.get<std::string>("rest_from");
    rest = read_pneumatic_dataset(file).tips_mm.row(0).transpose();
  } else if (params.has("model")) {
    throw Error("a learned model needs the arm's rest: rest_mm or rest_from",
                params.source() + ": " + params.path());
  }
  const double jitter = params.get_or<double>("rest_jitter_mm", 0.0);
  if (!(std::isfinite(jitter) && jitter >= 0.0)) {
    throw Error("must be finite and non-negative", key_where(params, "rest_jitter_mm"));
  }
  const double offset = params.get_or<double>("initial_offset_mm", 0.0);
  if (!(std::isfinite(offset) && offset >= 0.0)) {
    throw Error("must be finite and non-negative (mm), not " + std::to_string(offset),
                key_where(params, "initial_offset_mm"));
  }
  auto dynamics = std::make_unique<ModelDynamics>(std::move(model), rest, jitter, offset);
  std::unique_ptr<RobotHistoryModel> history = model_history(*dynamics);
  return std::make_unique<ReachEnv>(std::move(setup), std::move(dynamics), std::move(history));
}

namespace {

// What both reaching environments share; `model` says what stands for the arm.
EnvDescription reach_description(std::vector<EnvDescription::Parameter> dynamics) {
  std::vector<EnvDescription::Parameter> parameters = {
      {"task", "", "the paper's goal and plate: main, G1, G2 or G3"},
      {"goal_mm", "mm", "goal x y z, over the task's", true},
      {"obstacle_min_mm", "mm", "plate corner, over the task's", true},
      {"obstacle_max_mm", "mm", "plate corner, over the task's", true},
      {"boundary", "", "the boundary box B: paper or relaxed (GPRCA's)"},
      {"boundary_min_mm", "mm", "B's corner, over the boundary's", true},
      {"boundary_max_mm", "mm", "B's corner, over the boundary's", true},
      {"obstacle_distance", "", "O_dist to the plate (box) or to its plane (plane)"},
      {"success_distance_mm", "mm", "G_dist at which the goal counts as reached"},
      {"terminate_outside_boundary", "", "leaving B ends the episode"},
      {"rate_limit_bar", "bar", "largest change of a command taken in one step"},
      {"observe_command", "", "append the 9 normalised commands (20 entries)"},
      {"normalization.dataset", "",
       "data set whose tip ranges normalise the observation; "
       "default the twin's 10-minute set",
       true},
      {"normalization.tip_min_mm", "mm", "9 lower tip bounds, over the data set's", true},
      {"normalization.tip_max_mm", "mm", "9 upper tip bounds, over the data set's", true},
      {"normalization.distance_scale_mm", "mm", "G_dist, O_dist enter as 2d/scale − 1"}};
  parameters.insert(parameters.end(), dynamics.begin(), dynamics.end());
  return {
      .observation = {{"tips of modules 1, 2, 3, x y z each, normalised per axis by the data set's "
                       "range",
                       "1", physics::pneumatic::kChambers},
                      {"goal distance G_dist of module 3's tip, 2d/scale − 1", "1"},
                      {"plate distance O_dist of module 3's tip, 2d/scale − 1", "1"}},
      .action = {{"change of each chamber's normalised command (a = −1 ↔ 0 bar, 1 ↔ 1.5 bar)", "1",
                  physics::pneumatic::kChambers}},
      .reward =
          "eq. (2) of seed 002 on module 3's tip, cases added: −2 every step, −G_dist (mm) "
          "beyond 5 mm, −5 (20 − O_dist) within 20 mm of the plate, −10000 on a collision, "
          "−100 outside B",
      .episode_end =
          "terminated on success, a collision, leaving B "
          "(terminate_outside_boundary) or a non-finite state; truncated by the time "
          "limit (150 steps)",
      .parameters = std::move(parameters),
  };
}

}  // namespace

EnvDescription ReachEnv::robot_description() {
  std::vector<EnvDescription::Parameter> robot = {
      {"robot.backend", "", "twin, or bridge to the lab's devices"},
      {"robot.bridge.*", "", "with backend: bridge, the links (docs/hardware.md)", true},
      {"robot.control_period_s", "s", "how long a step holds the commands"},
      {"robot.observe_pressures", "", "PneumaticArm/Robot-v0's; the task reads the tips only"}};
  const std::vector<EnvDescription::Parameter> arm = arm_parameters("robot.");
  robot.insert(robot.end(), arm.begin(), arm.end());
  return reach_description(std::move(robot));
}

EnvDescription ReachEnv::model_description() {
  return reach_description(
      {{"model", "",
        "a model file or a `tendril model fit` run (9 tips, 9 pressures); default "
        "LinearArmModel, a stand-in that is not the arm",
        true},
       {"rest_mm", "mm", "the 9 tips with every chamber vented, where episodes start", true},
       {"rest_from", "", "else a pneumatic data set whose first row is the rest", true},
       {"rest_jitter_mm", "mm", "noise on the rest at each reset"},
       {"initial_offset_mm", "mm",
        "each module tip's rest moved at each reset by a uniform draw from the ball of this "
        "radius (the twin's drift: 40)"}});
}

}  // namespace tendril::envs::pneumatic
