#include "tendril/envs/tendon_arm/reach_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::tendon_arm {

namespace {

constexpr uint64_t kGoalStream = 0x7e4d;

}  // namespace

ReachEnv::ReachEnv(Setup setup, std::unique_ptr<Plant> plant)
    : setup_(std::move(setup)),
      plant_(std::move(plant)),
      observation_space_(Space::box(6 + (plant_ ? plant_->tendons() : 0),
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(plant_ ? plant_->tendons() : 1, 0.0f,
                               static_cast<float>(plant_ ? plant_->max_tension() : 1.0))),
      rng_(0, kGoalStream) {
  require(plant_ != nullptr, "no plant", setup_.id);
  require(std::isfinite(setup_.success_radius) && setup_.success_radius > 0.0,
          "success_radius must be positive", setup_.id);
  require(setup_.goal_settle_steps >= 1, "goal_settle_steps must be at least 1", setup_.id);
  require(std::isfinite(setup_.length) && setup_.length > 0.0, "length must be positive",
          setup_.id);
  tensions_ = Eigen::VectorXd::Zero(plant_->tendons());
  goal_tensions_ = tensions_;
  for (const char* key : {info_keys::kDistance, info_keys::kIsSuccess, info_keys::kNan}) {
    info_.set(key, 0.0);
  }
}

Observation ReachEnv::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed, kGoalStream);
  for (int k = 0; k < goal_tensions_.size(); ++k) {
    goal_tensions_[k] = rng_.uniform(0.0, plant_->max_tension());
  }
  goal_tensions_.array() -= goal_tensions_.minCoeff();
  plant_->reset(seed);
  for (int k = 0; k < setup_.goal_settle_steps; ++k) goal_ = plant_->step(goal_tensions_);
  require(plant_->finite() && goal_.allFinite(), "the plant's state is not finite at the goal",
          setup_.id);
  tip_ = plant_->reset(seed);
  require(plant_->finite() && tip_.allFinite(), "the plant's state is not finite at rest",
          setup_.id);
  tensions_.setZero();
  const double distance = (goal_ - tip_).norm();
  info_.set(info_keys::kDistance, distance);
  info_.set(info_keys::kIsSuccess, distance <= setup_.success_radius ? 1.0 : 0.0);
  info_.set(info_keys::kNan, 0.0);
  return observe();
}

Step ReachEnv::step(const Action& action) {
  check_action(action_space_, action, setup_.id);
  tensions_ = action.cast<double>().cwiseMax(0.0).cwiseMin(plant_->max_tension());
  const Eigen::Vector3d tip = plant_->step(tensions_);
  Step result;
  if (!plant_->finite() || !tip.allFinite()) {
    result.observation = observe();
    result.reward = -1.0;
    result.terminated = true;
    info_.set(info_keys::kIsSuccess, 0.0);
    info_.set(info_keys::kNan, 1.0);
    result.info = info_;
    return result;
  }
  tip_ = tip;
  const double distance = (goal_ - tip_).norm();
  result.observation = observe();
  result.reward = -distance / setup_.length;
  info_.set(info_keys::kDistance, distance);
  info_.set(info_keys::kIsSuccess, distance <= setup_.success_radius ? 1.0 : 0.0);
  info_.set(info_keys::kNan, 0.0);
  result.info = info_;
  return result;
}

Observation ReachEnv::observe() const {
  Observation observation(observation_space_.size());
  observation.head<3>() = (tip_ / setup_.length).cast<float>();
  observation.segment<3>(3) = ((goal_ - tip_) / setup_.length).cast<float>();
  observation.tail(tensions_.size()) = (tensions_ / plant_->max_tension()).cast<float>();
  return observation;
}

void ReachEnv::save_state(SnapshotWriter& out) const {
  out.section(setup_.id);
  plant_->save_state(out);
  out.put(rng_);
  out.put_matrix(goal_);
  out.put_matrix(tip_);
  out.put_matrix(tensions_);
  out.put_matrix(goal_tensions_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void ReachEnv::load_state(SnapshotReader& in) {
  in.section(setup_.id);
  load_all_or_nothing(*plant_, in, [&] {
    Rng rng = rng_;
    in.get(rng);
    Eigen::Vector3d goal, tip;
    in.get_matrix(goal);
    in.get_matrix(tip);
    Eigen::VectorXd tensions = tensions_;
    in.get_matrix(tensions);
    Eigen::VectorXd goal_tensions = goal_tensions_;
    in.get_matrix(goal_tensions);
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    rng_ = rng;
    goal_ = goal;
    tip_ = tip;
    tensions_ = tensions;
    goal_tensions_ = goal_tensions;
    info_ = std::move(info);
  });
}

bool ReachEnv::describe_scene(Scene& scene) const {
  plant_->describe_scene(scene);
  scene.spheres.push_back({"goal", goal_, setup_.success_radius});
  scene.values.emplace_back("distance [mm]", 1000.0 * (goal_ - tip_).norm());
  return true;
}

}  // namespace tendril::envs::tendon_arm
