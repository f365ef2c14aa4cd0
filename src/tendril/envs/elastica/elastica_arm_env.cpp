#include "tendril/envs/elastica/elastica_arm_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"

namespace tendril::envs::elastica {

ElasticaArmEnv::ElasticaArmEnv(Setup setup)
    : id_(std::move(setup.id)),
      arm_spec_(std::move(setup.arm)),
      arm_(physics::build_elastica_arm(arm_spec_)),
      // An implicit rod covers the same action period in steps of its own length.
      substeps_per_action_(
          arm_spec_.integrator == physics::RodIntegrator::kPositionVerlet
              ? setup.substeps_per_action
              : static_cast<int>(std::lround(setup.substeps_per_action * arm_spec_.time_step /
                                             arm_spec_.implicit_step))),
      observation_size_(setup.observation_size),
      nan_penalty_(setup.nan_penalty),
      obstacles_(std::move(setup.obstacles)),
      observation_space_(Space::box(observation_size_, -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(arm_spec_.actuation.action_size(), -1.0f, 1.0f)),
      muscle_targets_(Eigen::VectorXd::Zero(arm_spec_.actuation.action_size())),
      last_observation_(Observation::Zero(observation_size_)) {
  require(substeps_per_action_ >= 1, "substeps_per_action must be at least 1", id_);
  info_.set("distance", 0.0);
  info_.set("is_success", 0.0);
  info_.set("nan", 0.0);
}

Observation ElasticaArmEnv::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  arm_ = physics::build_elastica_arm(arm_spec_);
  reset_target(rng_);
  last_observation_ = observe();
  last_distance_ = (rod().tip_position() - target_position_).norm();
  return last_observation_;
}

Step ElasticaArmEnv::step(const Action& action) {
  begin_step(action);
  const bool finite = arm_.rod.advance(substeps_per_action_);
  return finish_step(finite);
}

const Eigen::VectorXd& ElasticaArmEnv::begin_step(const Action& action) {
  check_action(action_space_, action, id_);
  muscle_targets_ = action.cast<double>();
  arm_.muscles->set_targets(muscle_targets_);
  return muscle_targets_;
}

Step ElasticaArmEnv::finish_step(bool finite) {
  Step result;
  if (finite) {
    advance_target(rng_);
    result.observation = observe();
    finite = result.observation.allFinite();
  }
  if (finite) {
    const double distance = (rod().tip_position() - target_position_).norm();
    result.reward = task_reward(distance, info_);
    info_.set("distance", distance);
    info_.set("nan", 0.0);
    last_observation_ = result.observation;
    last_distance_ = distance;
  } else {
    // Seed 000: "a penalty term … was added any time a NaN was detected in the state
    // information … Detection of a NaN would cause the episode to end."
    result.observation = last_observation_;
    result.reward = nan_penalty_;
    result.terminated = true;
    info_.set("distance", last_distance_);
    info_.set("is_success", 0.0);
    info_.set("nan", 1.0);
  }
  result.info = info_;
  return result;
}

Observation ElasticaArmEnv::observe() const {
  Observation observation(observation_size_);
  ObservationWriter writer(observation);
  write_observation(writer);
  // A plain check rather than `require`, whose message would be built on every step.
  if (writer.written() != observation_size_) {
    throw Error("wrote " + std::to_string(writer.written()) + " observation values, expected " +
                    std::to_string(observation_size_),
                id_);
  }
  return observation;
}

void ElasticaArmEnv::write_arm_and_target(ObservationWriter& out) const {
  out.rod_nodes(rod());
  out.speed_and_direction(rod().tip_velocity());
  out.position(target_position_);
}

void ElasticaArmEnv::write_obstacles(ObservationWriter& out) const {
  for (const physics::Cylinder& cylinder : obstacles_) out.obstacle(cylinder);
}

void ElasticaArmEnv::save_state(SnapshotWriter& out) const {
  out.section(id_);
  arm_.rod.save_state(out);
  out.put_matrix(target_position_);
  out.put(rng_);
  out.put_matrix(muscle_targets_);
  out.put_matrix(last_observation_);
  out.put(last_distance_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
  save_task_state(out);
}

void ElasticaArmEnv::load_state(SnapshotReader& in) {
  in.section(id_);
  // Everything is read into copies first; the rod restores itself all or nothing.
  Snapshot rod_before;
  SnapshotWriter rod_writer(rod_before);
  arm_.rod.save_state(rod_writer);
  arm_.rod.load_state(in);
  try {
    Eigen::Vector3d target = target_position_;
    in.get_matrix(target);
    Rng rng = rng_;
    in.get(rng);
    Eigen::VectorXd muscle_targets = muscle_targets_;
    in.get_matrix(muscle_targets);
    Observation last_observation = last_observation_;
    in.get_matrix(last_observation);
    const double last_distance = in.get_double();
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    load_task_state(in);
    target_position_ = target;
    rng_ = rng;
    muscle_targets_ = std::move(muscle_targets);
    last_observation_ = std::move(last_observation);
    last_distance_ = last_distance;
    info_ = std::move(info);
  } catch (...) {
    SnapshotReader restore(rod_before);
    arm_.rod.load_state(restore);
    throw;
  }
}

bool ElasticaArmEnv::describe_scene(Scene& scene) const {
  scene.time = rod().time();
  const physics::RodState& state = rod().state();
  scene.rods.push_back({"arm", node_positions(), state.radii});
  scene.spheres.push_back({"target", target_position_, kTargetRadius});
  for (const physics::Cylinder& cylinder : obstacles_) {
    scene.cylinders.push_back({"obstacle", cylinder.start, cylinder.end(), cylinder.radius, false});
  }
  scene.values.emplace_back("distance", last_distance_);
  return true;
}

Eigen::Matrix3Xd ElasticaArmEnv::node_positions() const {
  return rod().sampled_node_positions(rod().n_elements() + 1);
}

void ElasticaArmEnv::set_target(const Eigen::Vector3d& position) {
  require(position.allFinite(), "target position must be finite", id_);
  target_position_ = position;
}

std::vector<EnvDescription::Entries> arm_state_entries() {
  const std::string nodes =
      "of the " + std::to_string(kRodSamples) + " sampled arm nodes, base to tip (lab frame)";
  return {{"x " + nodes, "m", kRodSamples},
          {"y " + nodes, "m", kRodSamples},
          {"z " + nodes, "m", kRodSamples},
          {"tip speed |v_tip|", "m/s"},
          {"tip direction of motion v_tip/|v_tip|, x y z (zeros at rest)", "1", 3}};
}

EnvDescription::Entries control_point_entries(const std::string& direction, int count) {
  return {direction + " torque control points, base to tip, × α_m = " +
              std::to_string(static_cast<int>(physics::SplineActuationSpec{}.max_torque)) + " N·m",
          "1", count};
}

}  // namespace tendril::envs::elastica
