#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

#include <cstdio>

namespace tendril::envs::sma_limb {

TwinLimbRobot::TwinLimbRobot(physics::SmaLimbSpec spec)
    : spec_(std::move(spec)), limb_(std::make_unique<physics::SmaLimb>(spec_, 0)) {}

LimbSample TwinLimbRobot::reset(uint64_t seed) {
  physics::SmaLimbSpec rested = spec_;
  for (int i = 0; i < physics::SmaActuator::kCoils; ++i) {
    rested.actuator.initial_degradation[i] = limb_->coil(i).degradation;
  }
  limb_ = std::make_unique<physics::SmaLimb>(rested, seed);
  return sample(limb_->last_reading());
}

LimbSample TwinLimbRobot::command(const std::array<int, 4>& pwm) {
  limb_->set_pwm(pwm);
  return sample(limb_->next_reading());
}

LimbSample TwinLimbRobot::sample(const physics::BendReading& reading) const {
  return {reading.time(), reading.angles_deg};
}

std::string TwinLimbRobot::description() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "SMA limb twin '%s': E %.3g MPa, %.0f mm long, %.0f mm diameter, tip mass %.0f g",
                spec_.name.c_str(), spec_.youngs_modulus * 1e-6, spec_.length * 1e3,
                2e3 * spec_.radius, spec_.tip_mass * 1e3);
  return text;
}

void TwinLimbRobot::save_state(SnapshotWriter& out) const { limb_->save_state(out); }

void TwinLimbRobot::load_state(SnapshotReader& in) {
  // The snapshot may hold worn coils: load into a limb built like the one that saved it, whose
  // every evolving quantity (degradation included) the snapshot then overwrites.
  limb_->load_state(in);
}

bool TwinLimbRobot::describe_scene(Scene& scene) const {
  limb_->describe(scene);
  return true;
}

void TwinLimbRobot::push(const Eigen::Vector2d& force_n, double duration_s) {
  // The limb's x and y axes (d1, d2 of its base) in the lab frame.
  const Eigen::Matrix3d base = limb_->rod().state().director(0);
  limb_->push(force_n.x() * base.row(0).transpose() + force_n.y() * base.row(1).transpose(),
              duration_s);
}

}  // namespace tendril::envs::sma_limb
