#include "tendril/envs/pneumatic/reach_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

namespace tendril::envs::pneumatic {

namespace {

constexpr double kMetresPerMillimetre = 1e-3;

Eigen::Vector3d module_3_tip(const TipVector& tips) { return tips.tail<3>(); }

Scene::Box box_in_metres(const std::string& role, const Eigen::AlignedBox3d& box) {
  Scene::Box drawn;
  drawn.role = role;
  drawn.centre = kMetresPerMillimetre * box.center();
  drawn.half_extents = 0.5 * kMetresPerMillimetre * box.sizes();
  return drawn;
}

}  // namespace

void ReachObservationSpec::validate() const {
  const char* where = "ReachObservationSpec";
  require(tip_min.allFinite() && tip_max.allFinite() && (tip_max.array() > tip_min.array()).all(),
          "the tip bounds must be finite with max > min per coordinate", where);
  require(std::isfinite(distance_scale) && distance_scale > 0.0, "distance_scale must be positive",
          where);
}

ReachObservationSpec ReachObservationSpec::twin_dataset() {
  // Per-coordinate extremes of the tips in the file that
  //   tendril data collect configs/pneumatic_arm/collect_twin_s0.yaml
  // writes (6000 rows), rounded outward to 0.1 mm.
  ReachObservationSpec spec;
  spec.tip_min << -38.9, -32.4, -227.4, -107.9, -110.8, -451.1, -220.5, -235.1, -672.1;
  spec.tip_max << 41.0, 42.1, -199.7, 130.1, 107.2, -394.7, 247.2, 228.6, -565.0;
  return spec;
}

ReachObservationSpec ReachObservationSpec::from_dataset(const PneumaticDataset& data) {
  ReachObservationSpec spec;
  spec.tip_min = data.tips_mm.colwise().minCoeff().transpose();
  spec.tip_max = data.tips_mm.colwise().maxCoeff().transpose();
  return spec;
}

ReachEnv::ReachEnv(Setup setup, std::unique_ptr<ArmDynamics> dynamics,
                   std::unique_ptr<RobotHistoryModel> history)
    : setup_(std::move(setup)),
      dynamics_(std::move(dynamics)),
      history_(std::move(history)),
      observation_space_(Space::box(setup_.observation.size(),
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(physics::pneumatic::kChambers, static_cast<float>(-setup_.max_delta),
                               static_cast<float>(setup_.max_delta))) {
  require(dynamics_ != nullptr, "no arm dynamics", setup_.id);
  setup_.task.validate();
  setup_.observation.validate();
  require(std::isfinite(setup_.max_delta) && setup_.max_delta > 0.0 &&
              std::isfinite(setup_.rate_limit) && setup_.rate_limit > 0.0,
          "max_delta and rate_limit must be positive", setup_.id);
  for (const char* key :
       {info_keys::kDistance, "goal_distance_mm", "obstacle_distance_mm", info_keys::kIsSuccess,
        info_keys::kCollision, "warning", "outside_boundary", "rate_limited", info_keys::kNan}) {
    info_.set(key, 0.0);
  }
  last_observation_ = Observation::Zero(setup_.observation.size());
}

Observation ReachEnv::reset(std::optional<uint64_t> seed) {
  command_.setConstant(-1.0);
  tips_ = dynamics_->reset(seed);
  require(dynamics_->finite() && tips_.allFinite(), "the arm's state is not finite at rest",
          setup_.id);
  const ReachOutcome outcome =
      evaluate_reach_step(setup_.task, module_3_tip(tips_), module_3_tip(tips_));
  for (const auto& entry : info_.entries()) info_.set(entry.first, 0.0);
  info_.set(info_keys::kDistance, kMetresPerMillimetre * outcome.goal_distance);
  info_.set("goal_distance_mm", outcome.goal_distance);
  info_.set("obstacle_distance_mm", outcome.obstacle_distance);
  last_observation_ = observe(tips_, outcome.goal_distance, outcome.obstacle_distance);
  return last_observation_;
}

Step ReachEnv::step(const Action& action) {
  check_action(action_space_, action, setup_.id);
  const ChamberVector delta = action.cast<double>();
  // The rate limit, with a relative tolerance for deltas that float rounding put just past it.
  const bool rate_limited = delta.cwiseAbs().maxCoeff() > setup_.rate_limit * (1.0 + 1e-6);
  if (rate_limited) return advance(command_, true);
  return advance((command_ + delta).cwiseMax(-1.0).cwiseMin(1.0), false);
}

Step ReachEnv::step_command(const ChamberVector& command) {
  require(command.allFinite(), "the command must be finite", setup_.id);
  // A change beyond the rate limit is scaled down as a whole, keeping its direction (clipping
  // each chamber alone would turn it toward the diagonal).
  ChamberVector change = command.cwiseMax(-1.0).cwiseMin(1.0) - command_;
  const double largest = change.cwiseAbs().maxCoeff();
  const bool rate_limited = largest > setup_.rate_limit;
  if (rate_limited) change *= setup_.rate_limit / largest;
  return advance((command_ + change).cwiseMax(-1.0).cwiseMin(1.0), rate_limited);
}

Observation ReachEnv::observation_of(const TipVector& tips_mm) const {
  const Eigen::Vector3d tip = module_3_tip(tips_mm);
  return observe(tips_mm, (tip - setup_.task.goal).norm(), obstacle_distance(setup_.task, tip));
}

Step ReachEnv::advance(const ChamberVector& command, bool rate_limited) {
  command_ = command;
  ChamberVector pressures;
  for (int k = 0; k < physics::pneumatic::kChambers; ++k) pressures[k] = pressure_of(command_[k]);

  const Eigen::Vector3d previous_tip = module_3_tip(tips_);
  const TipVector tips = dynamics_->step(pressures);
  Step result;
  if (!dynamics_->finite() || !tips.allFinite()) {
    // A non-finite arm ends the episode as leaving the boundary does.
    result.observation = last_observation_;
    result.reward = setup_.task.step_penalty + setup_.task.boundary_penalty;
    result.terminated = true;
    info_.set(info_keys::kNan, 1.0);
    info_.set(info_keys::kIsSuccess, 0.0);
    result.info = info_;
    return result;
  }
  tips_ = tips;
  const ReachOutcome outcome = evaluate_reach_step(setup_.task, previous_tip, module_3_tip(tips_));
  result.observation = observe(tips_, outcome.goal_distance, outcome.obstacle_distance);
  result.reward = outcome.reward;
  result.terminated = outcome.ends_episode;
  last_observation_ = result.observation;
  info_.set(info_keys::kDistance, kMetresPerMillimetre * outcome.goal_distance);
  info_.set("goal_distance_mm", outcome.goal_distance);
  info_.set("obstacle_distance_mm", outcome.obstacle_distance);
  info_.set(info_keys::kIsSuccess, outcome.success ? 1.0 : 0.0);
  info_.set(info_keys::kCollision, outcome.collision ? 1.0 : 0.0);
  info_.set("warning", outcome.warning ? 1.0 : 0.0);
  info_.set("outside_boundary", outcome.outside ? 1.0 : 0.0);
  info_.set("rate_limited", rate_limited ? 1.0 : 0.0);
  info_.set(info_keys::kNan, 0.0);
  result.info = info_;
  return result;
}

Observation ReachEnv::observe(const TipVector& tips, double goal_distance,
                              double obstacle_distance) const {
  const ReachObservationSpec& spec = setup_.observation;
  Observation observation(spec.size());
  for (int i = 0; i < 9; ++i) {
    observation[i] = static_cast<float>(
        2.0 * (tips[i] - spec.tip_min[i]) / (spec.tip_max[i] - spec.tip_min[i]) - 1.0);
  }
  observation[9] = static_cast<float>(2.0 * goal_distance / spec.distance_scale - 1.0);
  observation[10] = static_cast<float>(2.0 * obstacle_distance / spec.distance_scale - 1.0);
  if (spec.observe_command) {
    for (int k = 0; k < 9; ++k) observation[11 + k] = static_cast<float>(command_[k]);
  }
  return observation;
}

void ReachEnv::save_state(SnapshotWriter& out) const {
  out.section(setup_.id);
  dynamics_->save_state(out);
  out.put_matrix(command_);
  out.put_matrix(tips_);
  out.put_matrix(last_observation_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void ReachEnv::load_state(SnapshotReader& in) {
  in.section(setup_.id);
  load_all_or_nothing(*dynamics_, in, [&] {
    ChamberVector command;
    TipVector tips;
    Observation last = last_observation_;
    in.get_matrix(command);
    in.get_matrix(tips);
    in.get_matrix(last);
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    command_ = command;
    tips_ = tips;
    last_observation_ = std::move(last);
    info_ = std::move(info);
  });
}

bool ReachEnv::describe_scene(Scene& scene) const {
  dynamics_->describe_scene(scene);
  scene.spheres.push_back({"goal", kMetresPerMillimetre * setup_.task.goal,
                           kMetresPerMillimetre * setup_.task.success_distance});
  scene.boxes.push_back(box_in_metres("obstacle", setup_.task.obstacle));
  scene.boxes.push_back(box_in_metres("boundary", setup_.task.boundary));
  scene.values.emplace_back("goal distance [mm]", *info_.get("goal_distance_mm"));
  scene.values.emplace_back("obstacle distance [mm]", *info_.get("obstacle_distance_mm"));
  return true;
}

}  // namespace tendril::envs::pneumatic
