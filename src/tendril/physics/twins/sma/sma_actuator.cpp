#include "tendril/physics/twins/sma/sma_actuator.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

std::vector<Eigen::Vector3d> cardinal_offsets(double offset) {
  return {Eigen::Vector3d(offset, 0.0, 0.0), Eigen::Vector3d(-offset, 0.0, 0.0),
          Eigen::Vector3d(0.0, offset, 0.0), Eigen::Vector3d(0.0, -offset, 0.0)};
}

const char* const kCoilNames[4] = {"+x", "-x", "+y", "-y"};

}  // namespace

void SmaActuatorSpec::validate() const {
  coil.validate();
  const char* who = "SmaActuatorSpec";
  require(std::isfinite(tendon_offset) && tendon_offset > 0.0,
          "tendon_offset must be finite and positive", who);
  require(std::isfinite(thermal_step) && thermal_step > 0.0,
          "thermal_step must be finite and positive", who);
  for (double d : initial_degradation) {
    require(d >= 0.0 && d <= 1.0, "initial_degradation must lie in [0, 1]", who);
  }
}

SmaActuator::SmaActuator(const SmaActuatorSpec& spec)
    : spec_((spec.validate(), spec)),
      thermal_(spec.coil.thermal),
      tendons_(cardinal_offsets(spec.tendon_offset)) {
  for (int i = 0; i < kCoils; ++i) {
    coils_[i] = SmaCoilState::rested(spec_.coil, spec_.initial_degradation[i]);
  }
}

void SmaActuator::attach(const RodModel& model, const RodState& state) {
  tendons_.attach(model, state);
  thermal_time_ = state.time;
  update_tension_laws();
}

void SmaActuator::set_pwm(const std::array<int, 4>& pwm, double time) {
  for (int i = 0; i < kCoils; ++i) {
    if (pwm[i] < 0 || pwm[i] > kMaxPwm) {
      throw Error("PWM of coil " + std::string(kCoilNames[i]) + " must lie in 0-255, got " +
                      std::to_string(pwm[i]),
                  "SmaActuator");
    }
  }
  if ((pwm[0] > 0 && pwm[1] > 0) || (pwm[2] > 0 && pwm[3] > 0)) {
    throw Error("both coils of an antagonistic pair are on (PWM " + std::to_string(pwm[0]) + ", " +
                    std::to_string(pwm[1]) + ", " + std::to_string(pwm[2]) + ", " +
                    std::to_string(pwm[3]) + "); that would compress the limb",
                "SmaActuator");
  }
  if (time > thermal_time_) {
    advance_coils(time - thermal_time_);
    thermal_time_ = time;
    update_tension_laws();
  }
  pwm_ = pwm;
}

void SmaActuator::advance_coils(double h) {
  for (int i = 0; i < kCoils; ++i) {
    advance_coil(spec_.coil, thermal_, coils_[i], pwm_[i] / static_cast<double>(kMaxPwm), h);
  }
}

void SmaActuator::update_tension_laws() {
  for (int i = 0; i < kCoils; ++i) {
    const CoilTensionLaw law = coil_tension_law(spec_.coil, coils_[i]);
    tendons_.set_tension_law(i, law.at_rest, law.stiffness);
  }
}

void SmaActuator::start_step(const RodModel&, RodState& state, double) {
  if (state.time >= thermal_time_ + spec_.thermal_step) {
    while (state.time >= thermal_time_ + spec_.thermal_step) {
      advance_coils(spec_.thermal_step);
      thermal_time_ += spec_.thermal_step;
    }
    update_tension_laws();
  }
}

void SmaActuator::add_loads(const RodModel& model, RodState& state) {
  tendons_.add_loads(model, state);
}

void SmaActuator::save_state(SnapshotWriter& out) const {
  out.section("SmaActuator");
  for (const SmaCoilState& coil : coils_) {
    out.put(coil.wire_temperature);
    out.put(coil.body_temperature);
    out.put(coil.phase.martensite);
    out.put(coil.phase.temperature);
    out.put(coil.phase.heating);
    for (const PhaseState::Anchor* anchor :
         {&coil.phase.heating_anchor, &coil.phase.cooling_anchor}) {
      out.put(anchor->temperature);
      out.put(anchor->martensite);
      out.put(anchor->left_at);
    }
    out.put(coil.degradation);
  }
  for (int value : pwm_) out.put(static_cast<int64_t>(value));
  out.put(thermal_time_);
  tendons_.save_state(out);
}

void SmaActuator::load_state(SnapshotReader& in) {
  in.section("SmaActuator");
  std::array<SmaCoilState, 4> coils;
  for (SmaCoilState& coil : coils) {
    coil.wire_temperature = in.get_double();
    coil.body_temperature = in.get_double();
    coil.phase.martensite = in.get_double();
    coil.phase.temperature = in.get_double();
    coil.phase.heating = in.get_bool();
    for (PhaseState::Anchor* anchor : {&coil.phase.heating_anchor, &coil.phase.cooling_anchor}) {
      anchor->temperature = in.get_double();
      anchor->martensite = in.get_double();
      anchor->left_at = in.get_double();
    }
    coil.degradation = in.get_double();
  }
  std::array<int, 4> pwm{};
  for (int& value : pwm) value = static_cast<int>(in.get_int64());
  const double thermal_time = in.get_double();
  tendons_.load_state(in);  // reads everything before changing anything
  coils_ = coils;
  pwm_ = pwm;
  thermal_time_ = thermal_time;
}

}  // namespace tendril::physics
