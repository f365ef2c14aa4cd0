#include "tendril/envs/ur5/ur5_reach.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::ur5 {

namespace {

using Joints = physics::Ur5Arm::Joints;

constexpr const char* kOrientationError = "orientation_error";
constexpr const char* kActionPenaltyWeight = "action_penalty_weight";

std::string key_of(const Config& params, const std::string& key) {
  return params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key;
}

Eigen::VectorXd read_vector(const Config& params, const std::string& key,
                            const Eigen::VectorXd& fallback) {
  if (!params.has(key)) return fallback;
  const std::vector<double> values = params.get<std::vector<double>>(key);
  require(static_cast<Eigen::Index>(values.size()) == fallback.size(),
          "expected " + std::to_string(fallback.size()) + " values, got " +
              std::to_string(values.size()),
          key_of(params, key));
  return Eigen::Map<const Eigen::VectorXd>(values.data(), fallback.size());
}

Ur5Reach::Params validated(Ur5Reach::Params params) {
  params.validate();
  return params;
}

double read_positive(const Config& params, const std::string& key, double fallback) {
  const double value = params.get_or<double>(key, fallback);
  require(std::isfinite(value) && value > 0.0, "must be finite and positive", key_of(params, key));
  return value;
}

}  // namespace

void Ur5Reach::Params::validate() const {
  require(std::isfinite(max_delta) && max_delta > 0.0, "max_delta must be finite and positive",
          kId);
  require(frame_skip >= 1, "frame_skip must be at least 1", kId);
  require(std::isfinite(joint_noise) && joint_noise >= 0.0, "joint_noise must be finite and >= 0",
          kId);
  require(home.allFinite() &&
              (home.array().abs() + joint_noise <= physics::Ur5Arm::upper_limits().array()).all(),
          "home (with joint_noise) must lie within the joint limits", kId);
  require(std::isfinite(success_distance) && success_distance > 0.0,
          "success_distance must be finite and positive", kId);
  require(std::isfinite(success_angle) && success_angle > 0.0,
          "success_angle must be finite and positive", kId);
  scene.validate();
}

std::unique_ptr<Env> Ur5Reach::create(const Config& params) {
  Params p;
  p.max_delta = read_positive(params, "max_delta", p.max_delta);
  p.frame_skip = params.get_or<int>("frame_skip", p.frame_skip);
  require(p.frame_skip >= 1, "must be at least 1", key_of(params, "frame_skip"));
  p.scene.timestep = read_positive(params, "timestep", p.scene.timestep);
  p.joint_noise = params.get_or<double>("joint_noise", p.joint_noise);
  p.home = read_vector(params, "home", p.home);
  const std::string action_space = params.get_or<std::string>("action_space", "bounded");
  require(action_space == "bounded" || action_space == "unbounded",
          "must be 'bounded' or 'unbounded', got '" + action_space + "'",
          key_of(params, "action_space"));
  p.unbounded_action_space = action_space == "unbounded";
  p.success_distance = read_positive(params, "success_distance", p.success_distance);
  p.success_angle = read_positive(params, "success_angle", p.success_angle);
  p.scene.obstacle_centre = read_vector(params, "obstacle_centre", p.scene.obstacle_centre);
  p.scene.obstacle_half_extents =
      read_vector(params, "obstacle_half_extents", p.scene.obstacle_half_extents);
  if (params.has("model_file")) p.model_file = params.get<std::string>("model_file");
  p.targets = TargetRegion::from_config(params);
  p.reward = ReachRewardWeights::from_config(params);
  p.action_penalty = StepSchedule::from_config(params, "action_penalty", 0.05);
  return std::make_unique<Ur5Reach>(std::move(p));
}

Ur5Reach::Ur5Reach(Params params)
    : params_(validated(std::move(params))),
      arm_(params_.scene, params_.model_file),
      observation_space_(Space::box(kObservationSize, -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(params_.unbounded_action_space
                        ? Space::box(physics::ur5::kJoints, -std::numeric_limits<float>::infinity(),
                                     std::numeric_limits<float>::infinity())
                        : Space::box(physics::ur5::kJoints, -1.0f, 1.0f)),
      last_observation_(Observation::Zero(kObservationSize)) {
  info_.set(info_keys::kDistance, 0.0);
  info_.set(info_keys::kIsSuccess, 0.0);
  info_.set(info_keys::kCollision, 0.0);
  info_.set(info_keys::kContacts, 0.0);
  info_.set(kOrientationError, 0.0);
  info_.set(kActionPenaltyWeight, params_.action_penalty.value(0));
  info_.set(info_keys::kNan, 0.0);
  reset(0);
}

Observation Ur5Reach::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  Joints start = params_.home;
  for (int i = 0; i < physics::ur5::kJoints; ++i) {
    start[i] += rng_.uniform(-params_.joint_noise, params_.joint_noise);
  }
  arm_.place(start);
  target_ = sample_target(params_.targets, arm_.flange_position(), arm_.obstacle_centre(),
                          arm_.obstacle_half_extents(), rng_);
  previous_distance_ = (arm_.flange_position() - target_).norm();
  last_observation_ = observe(false);
  return last_observation_;
}

void Ur5Reach::plant(const Joints& q, const Eigen::Vector3d& target) {
  require(target.allFinite(), "target must be finite", kId);
  arm_.place(q);
  target_ = target;
  previous_distance_ = (arm_.flange_position() - target_).norm();
  last_observation_ = observe(arm_.contacts() > 0);
}

double Ur5Reach::orientation_error() const {
  const double cosine = -arm_.flange_rotation()(2, 2);  // tool axis · (0, 0, −1)
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

Step Ur5Reach::step(const Action& action) {
  check_action(action_space_, action, kId);
  const Eigen::VectorXd applied = action.cast<double>().cwiseMax(-1.0).cwiseMin(1.0);
  arm_.set_targets(arm_.joint_positions() + params_.max_delta * applied);
  const physics::Ur5Arm::Advance advance = arm_.advance(params_.frame_skip);
  const double penalty_weight = params_.action_penalty.value(total_steps_);
  ++total_steps_;
  info_.set(kActionPenaltyWeight, penalty_weight);

  Step result;
  result.observation = observe(advance.contacts > 0);
  if (!advance.stable || !result.observation.allFinite()) {
    result.observation = last_observation_;
    result.reward = -params_.reward.collision;
    result.terminated = true;
    info_.set(info_keys::kIsSuccess, 0.0);
    info_.set(info_keys::kNan, 1.0);
    result.info = info_;
    return result;
  }
  const double distance = (arm_.flange_position() - target_).norm();
  const double angle = orientation_error();
  const bool collided = advance.contacts > 0;
  const bool success =
      !collided && distance <= params_.success_distance && angle <= params_.success_angle;
  const ReachRewardTerms terms = reach_reward(params_.reward, previous_distance_, distance, angle,
                                              penalty_weight, applied, success, collided);
  result.reward = terms.total();
  result.terminated = success || collided;
  previous_distance_ = distance;
  last_observation_ = result.observation;
  info_.set(info_keys::kDistance, distance);
  info_.set(info_keys::kIsSuccess, success ? 1.0 : 0.0);
  info_.set(info_keys::kCollision, collided ? 1.0 : 0.0);
  info_.set(info_keys::kContacts, advance.contacts);
  info_.set(kOrientationError, angle);
  info_.set(info_keys::kNan, 0.0);
  result.info = info_;
  return result;
}

Observation Ur5Reach::observe(bool collided) const {
  Observation observation(kObservationSize);
  observation.segment<6>(0) = arm_.joint_positions().cast<float>();
  observation.segment<6>(6) = arm_.joint_velocities().cast<float>();
  observation.segment<3>(12) = arm_.flange_position().cast<float>();
  observation.segment<3>(15) = target_.cast<float>();
  observation[18] = collided ? 1.0f : 0.0f;
  return observation;
}

void Ur5Reach::save_state(SnapshotWriter& out) const {
  out.section(kId);
  arm_.save_state(out);
  out.put_matrix(target_);
  out.put(rng_);
  out.put(previous_distance_);
  out.put(static_cast<int64_t>(total_steps_));
  out.put_matrix(last_observation_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void Ur5Reach::load_state(SnapshotReader& in) {
  in.section(kId);
  load_all_or_nothing(arm_, in, [&] {
    Eigen::Vector3d target;
    in.get_matrix(target);
    Rng rng = rng_;
    in.get(rng);
    const double previous_distance = in.get_double();
    const int64_t total_steps = in.get_int64();
    Observation last_observation(kObservationSize);
    in.get_matrix(last_observation);
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    target_ = target;
    rng_ = rng;
    previous_distance_ = previous_distance;
    total_steps_ = total_steps;
    last_observation_ = std::move(last_observation);
    info_ = std::move(info);
  });
}

bool Ur5Reach::describe_scene(Scene& scene) const {
  arm_.describe(scene);
  scene.spheres.push_back({"target", target_, params_.success_distance});
  scene.values.emplace_back("distance", previous_distance_);
  scene.values.emplace_back(kOrientationError, orientation_error());
  return true;
}

EnvDescription Ur5Reach::description() {
  return {
      .observation = {{"joint angles q, base to wrist 3", "rad", physics::ur5::kJoints},
                      {"joint velocities q̇", "rad/s", physics::ur5::kJoints},
                      {"flange position x y z", "m", 3},
                      {"target position x y z", "m", 3},
                      {"collision flag (1: this step collided)", "1"}},
      .action = {{"joint-position deltas Δq = a · max_delta, a in [−1, 1]", "1",
                  physics::ur5::kJoints}},
      .reward =
          "seed 004 §3.1: w_p (d_{t−1} − d_t) + w_d exp(−α d_t) − w_o θ/π − λ_u ‖a‖² − w_t "
          "+ w_s [success] − w_c [collision], d the flange–target distance, θ the tool "
          "axis's angle to straight down",
      .episode_end =
          "terminated on success (d ≤ success_distance and θ ≤ success_angle), a "
          "collision or an unstable physics state; truncated by the time limit (1000 "
          "steps, 20 s)",
      .parameters =
          {{"max_delta", "rad", "joint change per step at |a| = 1"},
           {"frame_skip", "", "physics steps per action"},
           {"timestep", "s", "physics time step"},
           {"joint_noise", "rad", "uniform noise on every joint at reset"},
           {"home", "rad",
            "6 joint angles of the start pose; default tool down, flange at (0.25, 0, 0.10) m",
            true},
           {"action_space", "", "bounded ([−1, 1]) or unbounded (declared (−∞, ∞))"},
           {"success_distance", "m", "d that counts as reached"},
           {"success_angle", "rad", "θ that counts as tool down"},
           {"obstacle_centre", "m", "centre of the obstacle box; default (0.40, 0, 0.10) m", true},
           {"obstacle_half_extents", "m", "half extents of the box; default (0.05, 0.20, 0.10) m",
            true},
           {"model_file", "", "an MJCF with the scene's names, instead of the built-in", true},
           {"target_low", "m", "corner of the target region; default (0.52, −0.25, 0.15) m", true},
           {"target_high", "m", "opposite corner; default (0.70, 0.25, 0.30) m", true},
           {"target_obstacle_margin", "m", "no target this close to the box"},
           {"target_max_reach", "m", "no target farther from the shoulder"},
           {"progress_weight", "1/m", "w_p"},
           {"distance_weight", "1", "w_d"},
           {"distance_sensitivity", "1/m", "α"},
           {"orientation_weight", "1", "w_o"},
           {"time_penalty", "1", "w_t, per step"},
           {"success_bonus", "1", "w_s, once"},
           {"collision_penalty", "1", "w_c, once"},
           {"orientation_form", "", "penalty (−w_o θ/π) or bounded (w_o (1 − θ/π))"},
           {"action_penalty", "1", "λ_u, constant"},
           {"action_penalty_schedule.*", "1",
            "instead of action_penalty: {start, end, steps}, λ_u linear in steps", true}},
  };
}

}  // namespace tendril::envs::ur5
