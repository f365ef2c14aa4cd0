#include "tendril/envs/beam/beam_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::beam {

namespace {

constexpr const char* kVelocityErrorKey = "velocity_error";
constexpr const char* kEnergyKey = "energy";
constexpr const char* kInvertedCellsKey = "inverted_cells";

}  // namespace

int observation_size(BeamObservation observation) {
  switch (observation) {
    case BeamObservation::kTip:
      return 4;
    case BeamObservation::kSixPoints:
      return 14;
    case BeamObservation::kTrajectory:
      return 18;
  }
  return 0;
}

void BeamTaskSpec::validate() const {
  const std::string where = id.empty() ? "BeamTaskSpec" : id;
  require(std::isfinite(control_period) && control_period > 0.0,
          "control_period must be finite and positive", where);
  const double substeps = control_period / lattice.numerics.time_step;
  require(std::abs(substeps - std::round(substeps)) < 1e-9 * substeps && substeps >= 0.5,
          "control_period (" + std::to_string(control_period) +
              " s) must be a whole number of physics time steps (" +
              std::to_string(lattice.numerics.time_step) + " s)",
          where);
  require(std::isfinite(torque_scale) && torque_scale > 0.0,
          "torque_scale must be finite and positive", where);
  require(static_cast<int>(lattice.torque_rows.size()) == BeamEnv::kActions,
          "the beam needs five torque rows", where);
  require(std::isfinite(weights.distance) && std::isfinite(weights.velocity) &&
              std::isfinite(weights.energy),
          "reward weights must be finite", where);
  require(std::isfinite(max_distance) && max_distance >= 0.0,
          "max_distance must be non-negative (0: off)", where);
  require(std::isfinite(success_distance) && success_distance >= 0.0,
          "success_distance must be non-negative", where);
  require(std::isfinite(nan_penalty), "nan_penalty must be finite", where);
}

BeamEnv::BeamEnv(BeamTaskSpec spec, std::unique_ptr<TargetPath> target)
    : spec_((spec.validate(), std::move(spec))),
      target_(std::move(target)),
      beam_(spec_.lattice),
      substeps_(
          static_cast<int>(std::lround(spec_.control_period / spec_.lattice.numerics.time_step))),
      observation_space_(Space::box(observation_size(spec_.observation),
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(kActions, -1.0f, 1.0f)),
      torques_(Eigen::VectorXd::Zero(kActions)),
      actions_(Eigen::VectorXd::Zero(kActions)),
      last_observation_(Observation::Zero(observation_size(spec_.observation))) {
  require(target_ != nullptr, "a beam task needs a target path", spec_.id);
  info_.set(info_keys::kDistance, 0.0);
  info_.set(kVelocityErrorKey, 0.0);
  info_.set(kEnergyKey, 0.0);
  info_.set(info_keys::kIsSuccess, 0.0);
  info_.set(info_keys::kNan, 0.0);
  info_.set(kInvertedCellsKey, 0.0);
}

Observation BeamEnv::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  physics::LatticeState rest = beam_.lattice().state();
  rest.positions = beam_.lattice().model().rest_positions;
  rest.velocities.setZero();
  rest.time = 0.0;
  beam_.lattice().set_state(rest);
  torques_.setZero();
  actions_.setZero();
  beam_.couples().set_torques(torques_);
  target_->reset(rng_);
  distance_ = (beam_.tip_position() - target_->position()).norm();
  velocity_error_ = (beam_.tip_velocity() - target_->velocity()).norm();
  energy_ = 0.0;
  last_observation_ = observe();
  return last_observation_;
}

Step BeamEnv::step(const Action& action) {
  check_action(action_space_, action, spec_.id);
  actions_ = action.cast<double>().cwiseMax(-1.0).cwiseMin(1.0);
  torques_ = spec_.torque_scale * actions_;
  beam_.couples().set_torques(torques_);
  bool finite = beam_.lattice().advance(substeps_);

  Step result;
  if (finite) {
    target_->advance(rng_, spec_.control_period);
    result.observation = observe();
    finite = result.observation.allFinite();
  }
  if (finite) {
    distance_ = (beam_.tip_position() - target_->position()).norm();
    velocity_error_ = (beam_.tip_velocity() - target_->velocity()).norm();
    energy_ = energy_term();
    result.reward = follow_reward(spec_.weights, distance_, velocity_error_, energy_);
    result.terminated = spec_.max_distance > 0.0 && distance_ > spec_.max_distance;
    info_.set(info_keys::kDistance, distance_);
    info_.set(kVelocityErrorKey, velocity_error_);
    info_.set(kEnergyKey, energy_);
    info_.set(info_keys::kIsSuccess, distance_ <= spec_.success_distance ? 1.0 : 0.0);
    info_.set(info_keys::kNan, 0.0);
    info_.set(kInvertedCellsKey, beam_.inverted_cells());
    last_observation_ = result.observation;
  } else {
    result.observation = last_observation_;
    result.reward = spec_.nan_penalty;
    result.terminated = true;
    info_.set(info_keys::kIsSuccess, 0.0);
    info_.set(info_keys::kNan, 1.0);
  }
  result.info = info_;
  return result;
}

double BeamEnv::energy_term() const {
  const Eigen::VectorXd& tau = spec_.energy_in_newton_metres ? torques_ : actions_;
  double work = 0.0;
  for (int i = 0; i < kActions; ++i) work += tau[i] * beam_.row_angle(spec_.lattice.torque_rows[i]);
  return std::abs(work);
}

Observation BeamEnv::observe() const {
  Observation observation(observation_size(spec_.observation));
  int next = 0;
  const auto put = [&](const Eigen::Vector2d& v) {
    observation[next++] = static_cast<float>(v.x());
    observation[next++] = static_cast<float>(v.y());
  };
  if (spec_.observation == BeamObservation::kTip) {
    put(beam_.tip_position());
  } else {
    for (int row : spec_.lattice.torque_rows) put(beam_.row_centre(row));
    put(beam_.tip_position());
  }
  if (spec_.observation == BeamObservation::kTrajectory) put(beam_.tip_velocity());
  put(target_->position());
  if (spec_.observation == BeamObservation::kTrajectory) put(target_->velocity());
  return observation;
}

void BeamEnv::save_state(SnapshotWriter& out) const {
  out.section(spec_.id);
  beam_.lattice().save_state(out);
  target_->save_state(out);
  out.put(rng_);
  out.put_matrix(torques_);
  out.put_matrix(actions_);
  out.put_matrix(last_observation_);
  out.put(distance_);
  out.put(velocity_error_);
  out.put(energy_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void BeamEnv::load_state(SnapshotReader& in) {
  in.section(spec_.id);
  // The lattice and the target restore themselves all or nothing; undo them if a later read
  // fails.
  Snapshot before;
  SnapshotWriter before_writer(before);
  beam_.lattice().save_state(before_writer);
  target_->save_state(before_writer);
  try {
    beam_.lattice().load_state(in);
    target_->load_state(in);
    Rng rng = rng_;
    in.get(rng);
    Eigen::VectorXd torques = torques_, actions = actions_;
    in.get_matrix(torques);
    in.get_matrix(actions);
    Observation last_observation = last_observation_;
    in.get_matrix(last_observation);
    const double distance = in.get_double();
    const double velocity_error = in.get_double();
    const double energy = in.get_double();
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    rng_ = rng;
    torques_ = std::move(torques);
    actions_ = std::move(actions);
    last_observation_ = std::move(last_observation);
    distance_ = distance;
    velocity_error_ = velocity_error;
    energy_ = energy;
    info_ = std::move(info);
  } catch (...) {
    SnapshotReader restore(before);
    beam_.lattice().load_state(restore);
    target_->load_state(restore);
    throw;
  }
}

bool BeamEnv::describe_scene(Scene& scene) const {
  scene.time = time();
  const physics::LatticeModel& model = beam_.lattice().model();
  Scene::Lattice lattice;
  lattice.role = "arm";
  lattice.nodes = Eigen::Matrix3Xd::Zero(3, model.n_nodes());
  lattice.nodes.topRows<2>() = beam_.lattice().state().positions;
  for (const physics::Spring& spring : model.springs)
    lattice.springs.push_back({spring.a, spring.b});
  scene.lattices.push_back(std::move(lattice));
  const Eigen::Vector2d target = target_->position();
  scene.spheres.push_back({"target", Eigen::Vector3d(target.x(), target.y(), 0.0), 0.015});
  const Eigen::Matrix2Xd path = target_->polyline(65);
  Scene::Path line{"path", Eigen::Matrix3Xd::Zero(3, path.cols())};
  line.points.topRows<2>() = path;
  scene.paths.push_back(std::move(line));
  const Eigen::Vector2d tip = beam_.tip_position();
  scene.values = {{"distance", distance_},  {"velocity_error", velocity_error_},
                  {"energy", energy_},      {"tip_x", tip.x()},
                  {"tip_y", tip.y()},       {"target_x", target.x()},
                  {"target_y", target.y()}, {"level", target_->level()}};
  return true;
}

}  // namespace tendril::envs::beam
