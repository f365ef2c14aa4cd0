#include "tendril/physics/twins/sma/sma_limb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace tendril::physics {

namespace {

RodSpec rod_spec(const SmaLimbSpec& limb) {
  limb.validate();
  RodSpec spec;
  spec.n_elements = limb.n_elements;
  // The limb's first element is held in the mount (clamped), the other n − 1 make the free
  // length: the bend between the clamp and the tip frame then spans exactly the free length at
  // any resolution (a discrete rod bends only at its n − 1 joints).
  const double element = limb.length / (limb.n_elements - 1);
  spec.length = limb.length + element;
  spec.base_position = Eigen::Vector3d(0.0, 0.0, limb.hanging ? element : -element);
  spec.radius = limb.radius;
  spec.density = limb.density;
  spec.youngs_modulus = limb.youngs_modulus;
  spec.shear_modulus = limb.youngs_modulus / 3.0;  // incompressible: ν = 1/2
  spec.shear_coefficient = 27.0 / 28.0;            // PyElastica's value for a solid section
  spec.direction = Eigen::Vector3d(0.0, 0.0, limb.hanging ? -1.0 : 1.0);
  spec.normal = Eigen::Vector3d::UnitX();
  spec.tip_mass = limb.tip_mass;
  spec.rotary_inertia_scale = limb.rotary_inertia_scale;
  spec.integrator = limb.integrator;
  spec.time_step =
      limb.integrator == RodIntegrator::kPositionVerlet ? limb.time_step() : limb.implicit_step;
  return spec;
}

const char* const kCoilRoles[4] = {"+x", "-x", "+y", "-y"};

}  // namespace

SmaLimb::SmaLimb(const SmaLimbSpec& spec, uint64_t seed) : spec_(spec), rod_(rod_spec(spec)) {
  rod_.add<FixedEnd>();
  rod_.add<Gravity>();
  const double area = std::numbers::pi * spec_.radius * spec_.radius;
  const double second_moment = area * spec_.radius * spec_.radius / 4.0;
  // Every rate decays at damping_rate: γ_t = rate ρ A, γ_r = rate × (the elements' rotary
  // inertia per length).
  rod_.add<AnalyticalLinearDamping>(
      spec_.damping_rate * spec_.density * area,
      spec_.damping_rate * spec_.rotary_inertia_scale * spec_.density * second_moment);
  actuator_ = &rod_.add<SmaActuator>(spec_.actuator);
  push_ = &rod_.add<TipPush>();
  sensor_ = &rod_.add<BendSensor>(spec_.sensor, seed);
  last_reading_ = sensor_->sample(rod_.state());
}

void SmaLimb::set_pwm(const std::array<int, 4>& pwm) { actuator_->set_pwm(pwm, rod_.time()); }

BendReading SmaLimb::next_reading() {
  const int64_t target = sensor_->next_sample_ms() * spec_.steps_per_millisecond;
  if (finite_ && rod_.is_implicit()) {
    const double duration =
        1e-3 * static_cast<double>(target - steps_) / spec_.steps_per_millisecond;
    const int steps =
        std::max(1, static_cast<int>(std::ceil(duration / spec_.implicit_step - 1e-9)));
    if (duration > 0.0) finite_ = rod_.advance_by(duration, steps);
  } else if (finite_) {
    finite_ = rod_.advance(static_cast<int>(target - steps_));
  }
  steps_ = target;
  last_reading_ = sensor_->sample(rod_.state());  // also draws the next reading's time
  if (!finite_) last_reading_.angles_deg.setConstant(std::numeric_limits<double>::quiet_NaN());
  return last_reading_;
}

void SmaLimb::push(const Eigen::Vector3d& force, double duration) {
  require(std::isfinite(duration) && duration >= 0.0, "push duration must be finite and >= 0",
          "SmaLimb::push");
  push_->push(force, rod_.time() + duration);
}

void SmaLimb::save_state(SnapshotWriter& out) const {
  out.section("SmaLimb " + spec_.name);
  rod_.save_state(out);
  out.put(static_cast<int64_t>(steps_));
  out.put(static_cast<int64_t>(last_reading_.time_ms));
  out.put_matrix(last_reading_.angles_deg);
  out.put(finite_);
}

void SmaLimb::load_state(SnapshotReader& in) {
  in.section("SmaLimb " + spec_.name);
  Snapshot before;
  SnapshotWriter writer(before);
  rod_.save_state(writer);
  rod_.load_state(in);
  try {
    const int64_t steps = in.get_int64();
    BendReading reading;
    reading.time_ms = in.get_int64();
    in.get_matrix(reading.angles_deg);
    const bool finite = in.get_bool();
    steps_ = steps;
    last_reading_ = reading;
    finite_ = finite;
  } catch (...) {
    SnapshotReader restore(before);
    rod_.load_state(restore);
    throw;
  }
}

void SmaLimb::describe(Scene& scene) const {
  scene.time = time();
  const RodState& state = rod_.state();
  scene.rods.push_back({"limb", Eigen::Matrix3Xd(state.positions), state.radii});
  const double element = spec_.length / (spec_.n_elements - 1);  // held in the mount
  scene.boxes.push_back({"mount", Eigen::Vector3d(0.0, 0.0, (spec_.hanging ? 0.5 : -0.5) * element),
                         Eigen::Vector3d(0.015, 0.015, 0.5 * element),
                         Eigen::Quaterniond::Identity()});
  for (int i = 0; i < SmaActuator::kCoils; ++i) {
    scene.paths.push_back({"sma_coil", actuator_->coil_path(state, i)});
  }
  const Eigen::Vector2d angles = true_angles_deg();
  scene.values.emplace_back("theta_x_deg", angles.x());
  scene.values.emplace_back("theta_y_deg", angles.y());
  for (int i = 0; i < SmaActuator::kCoils; ++i) {
    const std::string name = std::string("coil ") + kCoilRoles[i] + " ";
    scene.values.emplace_back(name + "pwm", actuator_->pwm()[i]);
    scene.values.emplace_back(name + "wire_temperature_C", coil(i).wire_temperature);
    scene.values.emplace_back(name + "silicone_temperature_C", coil(i).body_temperature);
    scene.values.emplace_back(name + "martensite", coil(i).phase.martensite);
    scene.values.emplace_back(name + "tension_N", tension(i));
    scene.values.emplace_back(name + "degradation", coil(i).degradation);
  }
}

}  // namespace tendril::physics
