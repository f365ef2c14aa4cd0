#include "tendril/envs/tendon_arm/robot_env.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace tendril::envs::tendon_arm {

namespace {

// Seconds the straight arm hangs before the rest state is taken: its weight stretches it
// (ρ g L / E ≈ 0.5 % at the base) and the axial ringing this starts decays at the damping rate.
constexpr double kSettleSeconds = 1.0;

}  // namespace

std::unique_ptr<Env> RobotEnv::create(const Config& params) {
  return std::make_unique<RobotEnv>(arm_spec_from(params));
}

RobotEnv::RobotEnv(const ArmSpec& spec)
    : spec_(spec),
      rod_((spec.validate(), spec.rod_spec())),
      tendons_(nullptr),
      tensions_(Eigen::VectorXd::Zero(spec.tendons)),
      observation_space_(Space::box(3 + spec.tendons, -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(spec.tendons, 0.0f, static_cast<float>(spec.max_tension))) {
  rod_.add<physics::FixedEnd>();
  if (spec_.gravity) rod_.add<physics::Gravity>();
  // γ_t = rate ρ A, γ_r = rate ρ I: every translational and rotational rate decays at `rate`.
  const double area = std::numbers::pi * spec_.radius * spec_.radius;
  const double inertia = area * spec_.radius * spec_.radius / 4.0;
  rod_.add<physics::AnalyticalLinearDamping>(spec_.damping_rate * spec_.density * area,
                                             spec_.damping_rate * spec_.density * inertia);
  tendons_ = &rod_.add<physics::Tendons>(spec_.tendon_offsets());
  require(rod_.advance(static_cast<int>(std::lround(kSettleSeconds / spec_.time_step))),
          "the arm's state became non-finite while it settled", kId);
  rest_time_ = rod_.time();
  SnapshotWriter writer(rest_);
  rod_.save_state(writer);
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  last_observation_ = observe();
}

Observation RobotEnv::reset(std::optional<uint64_t> /*seed*/) {
  SnapshotReader reader(rest_);
  rod_.load_state(reader);
  tensions_.setZero();
  for (int k = 0; k < spec_.tendons; ++k) tendons_->set_tension(k, 0.0);
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  last_observation_ = observe();
  return last_observation_;
}

Step RobotEnv::step(const Action& action) {
  check_action(action_space_, action, kId);
  tensions_ = action.cast<double>().cwiseMax(0.0).cwiseMin(spec_.max_tension);
  for (int k = 0; k < spec_.tendons; ++k) tendons_->set_tension(k, tensions_[k]);
  Step result;
  if (rod_.advance(spec_.substeps())) {
    result.observation = observe();
    last_observation_ = result.observation;
    info_.set(info_keys::kNan, 0.0);
  } else {
    result.observation = last_observation_;
    result.terminated = true;
    info_.set(info_keys::kNan, 1.0);
  }
  info_.set("time_s", time());
  result.info = info_;
  return result;
}

Observation RobotEnv::observe() const {
  Observation observation(3 + spec_.tendons);
  observation.head<3>() = rod_.tip_position().cast<float>();
  for (int k = 0; k < spec_.tendons; ++k) {
    observation[3 + k] =
        static_cast<float>(tendons_->rest_path_length(k) - tendons_->path_length(rod_.state(), k));
  }
  return observation;
}

void RobotEnv::save_state(SnapshotWriter& out) const {
  out.section(kId);
  rod_.save_state(out);
  out.put_matrix(tensions_);
  out.put_matrix(last_observation_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void RobotEnv::load_state(SnapshotReader& in) {
  in.section(kId);
  load_all_or_nothing(rod_, in, [&] {
    Eigen::VectorXd tensions = tensions_;
    in.get_matrix(tensions);
    Observation last = last_observation_;
    in.get_matrix(last);
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    tensions_ = tensions;
    last_observation_ = std::move(last);
    info_ = std::move(info);
  });
}

bool RobotEnv::describe_scene(Scene& scene) const {
  scene.time = time();
  scene.rods.push_back({"arm", rod_.sampled_node_positions(rod_.n_elements() + 1),
                        Eigen::VectorXd::Constant(1, spec_.radius)});
  for (int k = 0; k < spec_.tendons; ++k) {
    scene.paths.push_back({"tendon", tendons_->path(rod_.state(), k)});
    scene.values.emplace_back("tension " + std::to_string(k + 1) + " [N]", tensions_[k]);
  }
  scene.spheres.push_back({"tip", rod_.tip_position(), 0.006});
  return true;
}

EnvDescription RobotEnv::description() {
  EnvDescription d;
  const int tendons = ArmSpec{}.tendons;
  d.observation = {{"tip position x, y, z (lab frame, origin at the clamped base, z up)", "m", 3},
                   {"travel of tendon k (reeled in from the unloaded straight arm)", "m", tendons}};
  d.action = {
      {"tension of tendon k (at 360° k / tendons from +x), clamped to [0, max]", "N", tendons}};
  d.reward = "0: a robot, no task";
  d.episode_end =
      "terminated only if the rod's state became non-finite (info nan = 1); truncated after "
      "600 steps (60 s)";
  d.parameters = arm_parameters("");
  return d;
}

}  // namespace tendril::envs::tendon_arm
