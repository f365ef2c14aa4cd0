#include "tendril/envs/elastica/structured_obstacles.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/elastica/intersection.hpp"
#include "tendril/envs/elastica/obstacles.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {

namespace {

constexpr const char* kId = "Elastica/StructuredObstacles-v0";
const Eigen::Vector3d kTarget(-0.8, 0.5, 0.15);  // m, SPEC M2 case 3

std::string key_of(const Config& params, const std::string& key) {
  return params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key;
}

physics::ElasticaArmSpec structured_arm(const StructuredObstacles::Params& params) {
  require(params.control_points >= 1,
          "control_points must be at least 1, got " + std::to_string(params.control_points), kId);
  const auto& positions = params.control_point_positions;
  require(positions.empty() || static_cast<int>(positions.size()) == params.control_points,
          "control_point_positions lists " + std::to_string(positions.size()) + " positions for " +
              std::to_string(params.control_points) + " control points",
          kId);
  for (std::size_t j = 0; j < positions.size(); ++j) {
    require(positions[j] > 0.0 && positions[j] < 1.0 && (j == 0 || positions[j] > positions[j - 1]),
            "control_point_positions must be strictly increasing fractions of L inside (0, 1)",
            kId);
  }
  require(std::isfinite(params.penalty_weight) && params.penalty_weight >= 0.0,
          "penalty_weight must be finite and non-negative", kId);

  physics::ElasticaArmSpec spec = physics::ElasticaArmSpec::structured_obstacles();
  spec.actuation.control_points = params.control_points;
  spec.actuation.positions = positions;
  if (params.obstacle_mode == StructuredObstacles::ObstacleMode::kPenalty) spec.obstacles.clear();
  spec.integrator = params.integrator;
  return spec;
}

}  // namespace

std::unique_ptr<Env> StructuredObstacles::create(const Config& params) {
  Params values;
  values.control_points = params.get_or<int>("control_points", values.control_points);
  values.control_point_positions =
      params.get_or<std::vector<double>>("control_point_positions", values.control_point_positions);
  const std::string mode = params.get_or<std::string>("obstacle_mode", "contact");
  if (mode == "penalty") {
    values.obstacle_mode = ObstacleMode::kPenalty;
  } else {
    require(mode == "contact", "obstacle_mode must be 'contact' or 'penalty', got '" + mode + "'",
            key_of(params, "obstacle_mode"));
  }
  values.penalty_weight = params.get_or<double>("penalty_weight", values.penalty_weight);
  try {
    values.integrator =
        physics::parse_integrator(params.get_or<std::string>("integrator", "verlet"));
  } catch (const Error& e) {
    throw Error(e.what_wrong(), key_of(params, "integrator"));
  }
  return std::make_unique<StructuredObstacles>(std::move(values));
}

StructuredObstacles::StructuredObstacles(Params params)
    : ElasticaArmEnv(Setup{kId, structured_arm(params), kSubstepsPerAction, kObservationSize,
                           kNanPenalty, structured_wall()}),
      params_(std::move(params)) {
  info().set("contacts", 0.0);
  info().set("penalty", 0.0);
}

void StructuredObstacles::reset_target(Rng& /*rng*/) { target_position_ = kTarget; }

void StructuredObstacles::write_observation(ObservationWriter& out) const {
  write_arm_and_target(out);
  write_obstacles(out);
}

double StructuredObstacles::task_reward(double distance, Info& info) const {
  info.set("is_success", distance <= kBonusRange ? 1.0 : 0.0);
  double reward = reach_reward(distance);
  if (params_.obstacle_mode == ObstacleMode::kPenalty) {
    // −φ f(S), f the fraction of elements inside an obstacle (see intersecting_elements).
    const int inside = intersecting_elements(rod(), kArmRadius, obstacles());
    const double penalty = params_.penalty_weight * inside / rod().n_elements();
    info.set("contacts", inside);
    info.set("penalty", penalty);
    reward -= penalty;
  } else {
    info.set("contacts", arm().contact->contacts());
  }
  return reward;
}

EnvDescription StructuredObstacles::description() {
  std::vector<EnvDescription::Entries> observation = arm_state_entries();
  observation.insert(observation.end(),
                     {{"target position x y z", "m", 3},
                      {"obstacles 0..7: 5 points along each axis, x of the 5, then y, then z", "m",
                       kObstacles * kObstacleBlock}});
  return {
      .observation = std::move(observation),
      .action = {control_point_entries("normal (d1)", Params{}.control_points)},
      .reward =
          "−d² + 0.5 if d ≤ 0.1 m, + 1.5 more if d ≤ 0.05 m, d the tip–target distance (seed 000, "
          "reach_reward); penalty mode: − penalty_weight × the fraction of elements inside an "
          "obstacle; −100 on a non-finite state",
      .episode_end = "terminated on a non-finite rod state; truncated by the time limit (5 s)",
      .parameters = {{"control_points", "", "normal control points (the action's size)"},
                     {"control_point_positions", "1",
                      "fractions of L, one per control point; "
                      "[] is equidistant"},
                     {"obstacle_mode", "", "contact (soft walls) or penalty (no contact)"},
                     {"penalty_weight", "1", "φ of the penalty mode"},
                     {"integrator", "", "verlet (the paper's), backward_euler or bdf2"}},
  };
}

}  // namespace tendril::envs::elastica
