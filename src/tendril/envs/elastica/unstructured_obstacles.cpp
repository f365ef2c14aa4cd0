#include "tendril/envs/elastica/unstructured_obstacles.hpp"

#include "tendril/envs/elastica/obstacles.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {

namespace {

const Eigen::Vector3d kTarget(-0.8, 0.5, 0.35);  // m, SPEC M2 case 4

physics::ElasticaArmSpec unstructured_arm(uint64_t obstacle_seed) {
  physics::ElasticaArmSpec spec = physics::ElasticaArmSpec::structured_obstacles();
  spec.actuation.control_points = 2;
  spec.actuation.positions.clear();
  spec.actuation.directions = {true, true, false};
  spec.obstacles = unstructured_nest(kTarget, obstacle_seed);
  return spec;
}

}  // namespace

std::unique_ptr<Env> UnstructuredObstacles::create(const Config& params) {
  return std::make_unique<UnstructuredObstacles>(params.get_or<uint64_t>("obstacle_seed", 0));
}

UnstructuredObstacles::UnstructuredObstacles(uint64_t obstacle_seed)
    : ElasticaArmEnv(Setup{"Elastica/UnstructuredObstacles-v0", unstructured_arm(obstacle_seed),
                           kSubstepsPerAction, kObservationSize, kNanPenalty,
                           unstructured_nest(kTarget, obstacle_seed)}),
      obstacle_seed_(obstacle_seed) {
  info().set("contacts", 0.0);
}

void UnstructuredObstacles::reset_target(Rng& /*rng*/) { target_position_ = kTarget; }

void UnstructuredObstacles::write_observation(ObservationWriter& out) const {
  write_arm_and_target(out);
  write_obstacles(out);
}

double UnstructuredObstacles::task_reward(double distance, Info& info) const {
  info.set("is_success", distance <= kBonusRange ? 1.0 : 0.0);
  info.set("contacts", arm().contact->contacts());
  return reach_reward(distance);
}

EnvDescription UnstructuredObstacles::description() {
  std::vector<EnvDescription::Entries> observation = arm_state_entries();
  observation.insert(observation.end(),
                     {{"target position x y z", "m", 3},
                      {"obstacles 0..11: 5 points along each axis, x of the 5, then y, then z", "m",
                       kObstacles * kObstacleBlock}});
  return {
      .observation = std::move(observation),
      .action = {control_point_entries("normal (d1)", 2),
                 control_point_entries("binormal (d2)", 2)},
      .reward =
          "−d² + 0.5 if d ≤ 0.1 m, + 1.5 more if d ≤ 0.05 m, d the tip–target distance (seed 000, "
          "reach_reward); −100 on a non-finite state",
      .episode_end = "terminated on a non-finite rod state; truncated by the time limit (5 s)",
      .parameters = {{"obstacle_seed", "",
                      "seed of the nest of cylinders, fixed for the "
                      "environment's life"}},
  };
}

}  // namespace tendril::envs::elastica
