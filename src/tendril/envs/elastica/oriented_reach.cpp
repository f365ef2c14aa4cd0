#include "tendril/envs/elastica/oriented_reach.hpp"

#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {

namespace {

// The box the target is drawn in (SPEC M2, the same as case 1's), m.
const Eigen::Vector3d kBoxLow(-0.6, 0.3, -0.6);
const Eigen::Vector3d kBoxHigh(0.6, 0.9, 0.6);

Eigen::Quaterniond canonical(Eigen::Quaterniond q) {
  q.normalize();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  return q;
}

physics::ElasticaArmSpec oriented_reach_arm() {
  physics::ElasticaArmSpec spec = physics::ElasticaArmSpec::tracking();
  spec.actuation.directions = {true, true, true};
  return spec;
}

}  // namespace

std::unique_ptr<Env> OrientedReach::create(const Config& /*params*/) {
  return std::make_unique<OrientedReach>();
}

OrientedReach::OrientedReach()
    : ElasticaArmEnv(Setup{"Elastica/OrientedReach-v0",
                           oriented_reach_arm(),
                           kSubstepsPerAction,
                           kObservationSize,
                           kNanPenalty,
                           {}}) {
  info().set("orientation", 0.0);
}

Eigen::Quaterniond OrientedReach::target_frame(const Eigen::Quaterniond& initial_tip,
                                               double theta) {
  return canonical(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()) * initial_tip);
}

void OrientedReach::reset_target(Rng& rng) {
  for (int c = 0; c < 3; ++c) target_position_[c] = rng.uniform(kBoxLow[c], kBoxHigh[c]);
  target_angle_ = rng.uniform(-0.5 * std::numbers::pi, 0.5 * std::numbers::pi);
  target_orientation_ = target_frame(rod().tip_quaternion(), target_angle_);
}

void OrientedReach::set_target_orientation(const Eigen::Quaterniond& orientation) {
  require(orientation.coeffs().allFinite() && orientation.norm() > 0.0,
          "target orientation must be a finite, non-zero quaternion", id());
  target_orientation_ = canonical(orientation);
}

void OrientedReach::write_observation(ObservationWriter& out) const {
  out.rod_nodes(rod());
  out.speed_and_direction(rod().tip_velocity());
  out.quaternion(rod().tip_quaternion());
  out.position(target_position_);
  out.speed_and_direction(Eigen::Vector3d::Zero());
  out.quaternion(target_orientation_);
}

double OrientedReach::task_reward(double distance, Info& info) const {
  const double p = orientation_penalty(rod().tip_quaternion(), target_orientation_);
  info.set("orientation", p);
  info.set("is_success", distance <= kBonusRange && p <= 0.05 ? 1.0 : 0.0);
  return oriented_reach_reward(distance, p);
}

void OrientedReach::save_task_state(SnapshotWriter& out) const {
  out.section("TargetOrientation");
  out.put_matrix(target_orientation_.coeffs());
  out.put(target_angle_);
}

void OrientedReach::load_task_state(SnapshotReader& in) {
  in.section("TargetOrientation");
  Eigen::Vector4d coefficients;
  in.get_matrix(coefficients);
  const double angle = in.get_double();
  target_orientation_.coeffs() = coefficients;
  target_angle_ = angle;
}

EnvDescription OrientedReach::description() {
  std::vector<EnvDescription::Entries> observation = arm_state_entries();
  observation.insert(observation.end(),
                     {{"tip quaternion w x y z, material → lab", "1", 4},
                      {"target position x y z", "m", 3},
                      {"target speed (always 0)", "m/s"},
                      {"target direction of motion, x y z (zeros: the target is still)", "1", 3},
                      {"target quaternion w x y z", "1", 4}});
  return {
      .observation = std::move(observation),
      .action = {control_point_entries("normal (d1)", 6), control_point_entries("binormal (d2)", 6),
                 control_point_entries("twist (d3)", 6)},
      .reward =
          "−d² − 0.5 p² plus the seed's bonus tiers in d and p (up to 6 − 2p at d ≤ 5 cm, "
          "p ≤ 0.05), p = 1 − (q_tip · q_target)² (seed 000 case 2, "
          "oriented_reach_reward); −10000 on a non-finite state",
      .episode_end = "terminated on a non-finite rod state; truncated by the time limit (2 s)",
      .parameters = {},
  };
}

}  // namespace tendril::envs::elastica
