// ReachEnv's parameters from an experiment's env.params: TendonArm/Reach-v0 and
// TendonArm/LearnedReach-v0.
#include <cmath>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/tendon_arm/constant_curvature_model.hpp"
#include "tendril/envs/tendon_arm/model_plant.hpp"
#include "tendril/envs/tendon_arm/reach_env.hpp"
#include "tendril/envs/tendon_arm/robot_env.hpp"
#include "tendril/envs/tendon_arm/robot_plant.hpp"

namespace tendril::envs::tendon_arm {

namespace {

ReachEnv::Setup setup_from(const Config& params, std::string id, double length) {
  ReachEnv::Setup setup;
  setup.id = std::move(id);
  setup.length = length;
  setup.success_radius = params.get_or<double>("success_radius_m", setup.success_radius);
  if (!(std::isfinite(setup.success_radius) && setup.success_radius > 0.0)) {
    throw Error("must be positive", params.where("success_radius_m"));
  }
  setup.goal_settle_steps = params.get_or<int>("goal_settle_steps", setup.goal_settle_steps);
  if (setup.goal_settle_steps < 1)
    throw Error("must be at least 1", params.where("goal_settle_steps"));
  return setup;
}

EnvDescription reach_description(std::vector<EnvDescription::Parameter> plant) {
  EnvDescription d;
  const int tendons = ArmSpec{}.tendons;
  d.observation = {{"tip x, y, z over the arm's length L", "1", 3},
                   {"goal − tip, x, y, z, over L", "1", 3},
                   {"tension held on tendon k over max_tension_n", "1", tendons}};
  d.action = {{"tension of tendon k, clamped to [0, max_tension_n]", "N", tendons}};
  d.reward =
      "−|goal − tip| / L every step (0 at the goal). The goal is where the plant's tip comes to "
      "rest under random held tensions, so every goal is reachable on the plant";
  d.episode_end =
      "truncated after 50 steps (5 s); terminated only by a non-finite plant (info nan = 1); "
      "info is_success when the tip is within success_radius_m";
  d.parameters = {{"success_radius_m", "m", "distance counted as success"},
                  {"goal_settle_steps", "", "control periods the goal's tensions are held"}};
  d.parameters.insert(d.parameters.end(), plant.begin(), plant.end());
  return d;
}

}  // namespace

EnvDescription ReachEnv::robot_description() { return reach_description(arm_parameters("robot.")); }

EnvDescription ReachEnv::model_description() {
  return reach_description(
      {{"model", "",
        "required: a model file or a `tendril model fit` run of the arm (tip m, tensions N), or "
        "constant_curvature (a torch-free stand-in, not the arm)"},
       {"rest_m", "m", "the tip hanging at rest, where episodes start; default the twin's", true},
       {"max_tension_n", "N", "the action bound (the robot's)"},
       {"length_m", "m", "the scale of observation and reward (the robot's length)"}});
}

std::unique_ptr<Env> ReachEnv::create_on_robot(const Config& params) {
  const Config robot_params = params.child("robot");
  const ArmSpec spec = arm_spec_from(robot_params);
  Setup setup = setup_from(params, kRobotId, spec.length);
  return std::make_unique<ReachEnv>(std::move(setup),
                                    std::make_unique<RobotPlant>(RobotEnv::create(robot_params)));
}

std::unique_ptr<Env> ReachEnv::create_on_model(const Config& params) {
  if (!params.has("model")) {
    throw Error(std::string(kModelId) +
                    " needs `model:` (a model file or a `tendril model fit` "
                    "run of the tendon arm, or constant_curvature for the torch-free stand-in)",
                params.where("model"));
  }
  ArmSpec arm;
  arm.length = params.get_or<double>("length_m", arm.length);
  arm.max_tension = params.get_or<double>("max_tension_n", arm.max_tension);
  if (!(std::isfinite(arm.length) && arm.length > 0.0)) {
    throw Error("must be positive", params.where("length_m"));
  }
  if (!(std::isfinite(arm.max_tension) && arm.max_tension > 0.0)) {
    throw Error("must be positive", params.where("max_tension_n"));
  }
  Eigen::Vector3d rest = RobotEnv::kDefaultRest;
  if (params.has("rest_m")) {
    const std::vector<double> values = params.get<std::vector<double>>("rest_m");
    if (values.size() != 3) throw Error("needs 3 numbers (x, y, z in m)", params.where("rest_m"));
    rest = Eigen::Vector3d(values[0], values[1], values[2]);
    if (!rest.allFinite()) throw Error("must be finite", params.where("rest_m"));
  }
  Setup setup = setup_from(params, kModelId, arm.length);
  const std::string name = params.get<std::string>("model");
  std::shared_ptr<DynamicsModel> model;
  if (name == ConstantCurvatureModel::kName) {
    model = std::make_shared<ConstantCurvatureModel>(arm, rest);
  } else {
    model = load_dynamics_model(name, kModelId);
  }
  return std::make_unique<ReachEnv>(std::move(setup),
                                    std::make_unique<ModelPlant>(model, rest, arm.max_tension));
}

}  // namespace tendril::envs::tendon_arm
