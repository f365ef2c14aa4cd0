#include "tendril/envs/elastica/tracking_3d.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {

namespace {

physics::ElasticaArmSpec tracking_arm(physics::RodIntegrator integrator) {
  physics::ElasticaArmSpec spec = physics::ElasticaArmSpec::tracking();
  spec.integrator = integrator;
  return spec;
}

}  // namespace

Tracking3D::Options Tracking3D::Options::from_config(const Config& params) {
  Options options;
  try {
    options.integrator =
        physics::parse_integrator(params.get_or<std::string>("integrator", "verlet"));
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": integrator");
  }
  options.lockstep_rods = params.get_or<bool>("lockstep_rods", false);
  return options;
}

std::unique_ptr<Env> Tracking3D::create(const Config& params) {
  return std::make_unique<Tracking3D>(Options::from_config(params).integrator);
}

Tracking3D::Tracking3D(physics::RodIntegrator integrator)
    : ElasticaArmEnv(Setup{"Elastica/Tracking3D-v0",
                           tracking_arm(integrator),
                           kSubstepsPerAction,
                           kObservationSize,
                           kNanPenalty,
                           {}}) {}

void Tracking3D::reset_target(Rng& rng) {
  motion_.reset(rng);
  target_position_ = motion_.position();
}

void Tracking3D::advance_target(Rng& rng) {
  motion_.advance(rng);
  target_position_ = motion_.position();
}

void Tracking3D::set_target(const Eigen::Vector3d& position) {
  set_target_state(position, motion_.velocity());
}

void Tracking3D::set_target_state(const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& velocity) {
  motion_.set_state(position, velocity);
  target_position_ = motion_.position();
}

void Tracking3D::write_observation(ObservationWriter& out) const {
  write_arm_and_target(out);
  out.speed_and_direction(motion_.velocity());
}

double Tracking3D::task_reward(double distance, Info& info) const {
  info.set("is_success", distance <= kBonusRange ? 1.0 : 0.0);
  return reach_reward(distance);
}

void Tracking3D::save_task_state(SnapshotWriter& out) const {
  out.section("TargetMotion");
  out.put_matrix(motion_.position());
  out.put_matrix(motion_.velocity());
  out.put(static_cast<int64_t>(motion_.updates()));
}

void Tracking3D::load_task_state(SnapshotReader& in) {
  in.section("TargetMotion");
  Eigen::Vector3d position, velocity;
  in.get_matrix(position);
  in.get_matrix(velocity);
  const int64_t updates = in.get_int64();
  motion_.set_state(position, velocity, updates);
}

EnvDescription Tracking3D::description() {
  std::vector<EnvDescription::Entries> observation = arm_state_entries();
  observation.insert(observation.end(), {{"target position x y z", "m", 3},
                                         {"target speed (0.5 m/s)", "m/s"},
                                         {"target direction of motion, x y z", "1", 3}});
  return {
      .observation = std::move(observation),
      .action = {control_point_entries("normal (d1)", 6),
                 control_point_entries("binormal (d2)", 6)},
      .reward =
          "−d² + 0.5 if d ≤ 0.1 m, + 1.5 more if d ≤ 0.05 m, d the tip–target distance (seed 000, "
          "reach_reward); −1000 on a non-finite state",
      .episode_end = "terminated on a non-finite rod state; truncated by the time limit (10 s)",
      .parameters = {{"integrator", "", "verlet (the paper's), backward_euler or bdf2"},
                     {"lockstep_rods", "",
                      "true: the n_envs copies of a vector env advance their rods together in "
                      "one RodPool, vectorized across rods, with bit-identical results (verlet "
                      "only; faster from about 8 envs, bench/pooled_arm_env_bench.cpp)"}},
  };
}

}  // namespace tendril::envs::elastica
