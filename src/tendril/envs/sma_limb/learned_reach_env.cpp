#include "tendril/envs/sma_limb/learned_reach_env.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/sma_limb/linear_limb_model.hpp"

namespace tendril::envs::sma_limb {

LearnedReachEnv::LearnedReachEnv(std::shared_ptr<DynamicsModel> model, LearnedReachOptions options,
                                 uint64_t seed)
    : batch_(std::move(model), options, 1, seed),
      observation_space_(batch_.observation_space()),
      action_space_(LearnedReachBatch::action_space()),
      action_(BatchMatrix::Zero(1, 2)) {}

std::shared_ptr<DynamicsModel> LearnedReachEnv::open_model(const Config& params) {
  if (!params.has("model")) return std::make_shared<LinearLimbModel>();
  return load_dynamics_model(params.get<std::string>("model"), kId);
}

std::unique_ptr<Env> LearnedReachEnv::create(const Config& params) {
  const uint64_t seed = params.get_or<uint64_t>("seed", 0);
  LearnedReachOptions options = LearnedReachOptions::from_config(params);
  return std::make_unique<LearnedReachEnv>(open_model(params), options, seed);
}

Observation LearnedReachEnv::observe() const {
  Observation observation(batch_.observation_size());
  batch_.observe(0, observation);
  return observation;
}

Observation LearnedReachEnv::reset(std::optional<uint64_t> seed) {
  batch_.reset(0, seed);
  needs_reset_ = false;
  return observe();
}

Step LearnedReachEnv::step(const Action& action) {
  check_action(action_space_, action, kId);
  require(!needs_reset_, "step before reset or after the episode ended", kId);
  action_.row(0) = action.transpose();
  batch_.step(action_);
  Step result;
  result.observation = observe();
  result.reward = batch_.reward(0);
  result.terminated = batch_.terminated(0);
  result.info = batch_.info(0);
  needs_reset_ = result.terminated;
  return result;
}

void LearnedReachEnv::save_state(SnapshotWriter& out) const {
  out.section(kId);
  out.put(needs_reset_);
  batch_.save_state(out);
}

void LearnedReachEnv::load_state(SnapshotReader& in) {
  in.section(kId);
  const bool needs_reset = in.get_bool();
  batch_.load_state(in);
  needs_reset_ = needs_reset;
}

bool LearnedReachEnv::describe_scene(Scene& scene) const {
  const Eigen::Vector4d state = batch_.state(0);
  const Eigen::Vector4d& goal = batch_.goal(0);
  scene.values.emplace_back("theta_x_deg", state[0]);
  scene.values.emplace_back("theta_y_deg", state[1]);
  scene.values.emplace_back("goal_theta_x_deg", goal[0]);
  scene.values.emplace_back("goal_theta_y_deg", goal[1]);
  scene.values.emplace_back("tolerance_deg", batch_.tolerance(0));
  return true;
}

}  // namespace tendril::envs::sma_limb
