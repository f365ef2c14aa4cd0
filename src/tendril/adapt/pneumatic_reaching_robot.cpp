#include "tendril/adapt/pneumatic_reaching_robot.hpp"

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::adapt {

namespace {

constexpr const char* kWhere = "adapt::PneumaticReachingRobot";

envs::pneumatic::ReachEnv* as_reach_env(const std::unique_ptr<Env>& env) {
  auto* reach = dynamic_cast<envs::pneumatic::ReachEnv*>(env.get());
  require(reach != nullptr, "the environment is not the pneumatic arm's reaching task", kWhere);
  return reach;
}

envs::pneumatic::ChamberVector chambers_of(const Eigen::VectorXd& command) {
  require(command.size() == 9, "the command must have 9 values", kWhere);
  return command;
}

bool flag(const Info& info, const char* key) { return info.get(key).value_or(0.0) != 0.0; }

}  // namespace

PneumaticReachingRobot::PneumaticReachingRobot(std::unique_ptr<Env> reach_env)
    : owner_(std::move(reach_env)), env_(as_reach_env(owner_)), command_(env_->command()) {}

std::unique_ptr<PneumaticReachingRobot> PneumaticReachingRobot::on_robot(const Config& params) {
  return std::make_unique<PneumaticReachingRobot>(
      envs::pneumatic::ReachEnv::create_on_robot(params));
}

std::unique_ptr<PneumaticReachingRobot> PneumaticReachingRobot::on_model(const Config& params) {
  return std::make_unique<PneumaticReachingRobot>(
      envs::pneumatic::ReachEnv::create_on_model(params));
}

void PneumaticReachingRobot::read_status(const Info& info, double reward) {
  status_.goal_distance = info.get("goal_distance_mm").value_or(0.0);
  status_.obstacle_distance = info.get("obstacle_distance_mm").value_or(0.0);
  status_.reward = reward;
  status_.success = flag(info, info_keys::kIsSuccess);
  status_.collision = flag(info, info_keys::kCollision);
  status_.outside = flag(info, "outside_boundary");
  status_.rate_limited = flag(info, "rate_limited");
}

std::vector<std::string> PneumaticReachingRobot::state_names() const {
  std::vector<std::string> names;
  for (int module = 1; module <= 3; ++module) {
    for (const char* axis : {"x", "y", "z"}) {
      names.push_back("tip_m" + std::to_string(module) + "_" + axis + "_mm");
    }
  }
  return names;
}

Eigen::VectorXd PneumaticReachingRobot::reset(std::optional<uint64_t> seed) {
  env_->reset(seed);
  command_ = env_->command();
  // ReachEnv's reset sets its info without a step; read the distances from the tips.
  const Eigen::Vector3d tip = env_->tips().tail<3>();
  status_ = ReachStatus{};
  status_.goal_distance = (tip - env_->task().goal).norm();
  status_.obstacle_distance = envs::pneumatic::obstacle_distance(env_->task(), tip);
  return env_->tips();
}

Eigen::VectorXd PneumaticReachingRobot::step(const Eigen::VectorXd& command) {
  const Step step = env_->step_command(chambers_of(command));
  require(step.info.get(info_keys::kNan).value_or(0.0) == 0.0, "the arm's state became non-finite",
          kWhere);
  command_ = env_->command();
  read_status(step.info, step.reward);
  return env_->tips();
}

Observation PneumaticReachingRobot::observation_of(const Eigen::VectorXd& state) const {
  require(state.size() == 9, "the state must have 9 values", kWhere);
  return env_->observation_of(state);
}

Eigen::VectorXd PneumaticReachingRobot::command_after(const Action& action) const {
  require(action.size() == 9 && action.allFinite(), "the action must be 9 finite values", kWhere);
  const envs::pneumatic::ChamberVector delta = action.cast<double>();
  // As ReachEnv::step: a delta beyond the rate limit is not taken.
  if (delta.cwiseAbs().maxCoeff() > env_->rate_limit() * (1.0 + 1e-6)) return command_;
  return (command_ + delta).cwiseMax(-1.0).cwiseMin(1.0);
}

Eigen::Vector3d PneumaticReachingRobot::task_point(const Eigen::VectorXd& state) const {
  require(state.size() == 9, "the state must have 9 values", kWhere);
  return state.tail<3>();
}

Eigen::Vector3d PneumaticReachingRobot::goal() const { return env_->task().goal; }

double PneumaticReachingRobot::success_distance() const { return env_->task().success_distance; }

PneumaticHistoryModel::PneumaticHistoryModel(const Config& learned_reach_params)
    : owner_(envs::pneumatic::ReachEnv::create_on_model(learned_reach_params)) {
  auto& reach = *as_reach_env(owner_);
  model_ = dynamic_cast<envs::pneumatic::ModelDynamics*>(&reach.dynamics());
  require(model_ != nullptr, "the learned-reach environment holds no learned model", kWhere);
}

void PneumaticHistoryModel::reset(const Eigen::VectorXd& state) {
  require(state.size() == 9, "the state must have 9 values", kWhere);
  model_->reset_to(state);
}

Eigen::VectorXd PneumaticHistoryModel::predict(const Eigen::VectorXd& command) {
  envs::pneumatic::ChamberVector pressures;
  const envs::pneumatic::ChamberVector normalised = chambers_of(command);
  for (int k = 0; k < 9; ++k) {
    pressures[k] = envs::pneumatic::ReachEnv::pressure_of(normalised[k]);
  }
  return model_->predict_next(pressures);
}

void PneumaticHistoryModel::follow(const Eigen::VectorXd& state) {
  require(state.size() == 9, "the state must have 9 values", kWhere);
  model_->follow(state);
}

}  // namespace tendril::adapt
