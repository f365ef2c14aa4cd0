#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/twins/pneumatic/mass_eccentricity.hpp"

namespace tendril::physics::pneumatic {

namespace {

// Random streams of one twin, derived from its seeds.
enum Stream : uint64_t {
  kDriftStream = 1,
  kSensorStream = 2,
  kInstanceStream = 3,
  kElasticityStream = 4
};

RodSpec rod_spec(const PneumaticArmSpec& spec) {
  spec.validate();
  RodSpec rod;
  rod.n_elements = spec.n_elements();
  rod.length = spec.length;
  rod.radius = spec.radius;
  rod.density = spec.density;
  rod.youngs_modulus = spec.youngs_modulus;
  rod.shear_modulus = shear_modulus_from_poisson(spec.youngs_modulus, spec.poisson_ratio);
  rod.base_position = Eigen::Vector3d::Zero();
  // Hanging down; d1 = +x, so d2 = d3 × d1 = −y.
  rod.direction = -Eigen::Vector3d::UnitZ();
  rod.normal = Eigen::Vector3d::UnitX();
  rod.time_step = spec.time_step;
  rod.integrator = spec.integrator;
  return rod;
}

MotionCaptureSpec sensor_spec(const PneumaticArmSpec& spec) {
  MotionCaptureSpec sensor = spec.sensor;
  sensor.marker_noise = spec.effects.sensor_noise ? spec.effects.marker_noise : 0.0;
  return sensor;
}

// Straight-arm estimate of how far a module's bend angle moves the arm's tip, per radian: half
// the module's own length plus everything below it.
constexpr std::array<double, kModules> kTipLevers{2.5, 1.5, 0.5};  // × module length

}  // namespace

PneumaticArm::PneumaticArm(const PneumaticArmSpec& spec)
    : spec_(spec),
      rod_(rod_spec(spec)),
      capture_(sensor_spec(spec), Rng(0, kSensorStream)),
      drift_rng_(0, kDriftStream),
      elasticity_rng_(0, kElasticityStream),
      steps_per_sample_(spec.steps_per_sample()) {
  const Eigen::Vector3d gravity(0.0, 0.0, -spec_.gravity);
  Vectors offsets = Vectors::Zero(3, spec_.n_elements());
  if (spec_.effects.imbalance) {
    Rng instance(spec_.instance_seed, kInstanceStream);
    for (int k = 0; k < kChambers; ++k) {
      gains_[k] = 1.0 + instance.uniform(-spec_.effects.gain_spread, spec_.effects.gain_spread);
    }
    for (int m = 0; m < kModules; ++m) {
      const double angle = instance.uniform(0.0, 2.0 * std::numbers::pi);
      for (int i = m * spec_.elements_per_module; i < (m + 1) * spec_.elements_per_module; ++i) {
        offsets(0, i) = spec_.effects.eccentricity * std::cos(angle);
        offsets(1, i) = spec_.effects.eccentricity * std::sin(angle);
      }
    }
  }

  ModuleActuationSpec actuation;
  actuation.elements_per_module = spec_.elements_per_module;
  actuation.module_length = spec_.module_length();
  actuation.bend_per_bar = spec_.bend_per_bar;
  actuation.extension_per_bar = spec_.extension_per_bar;
  for (int m = 0; m < kModules; ++m) {
    for (int c = 0; c < kChambersPerModule; ++c) {
      // Robot-frame angle ψ from +x toward +y; with d1 = +x and d2 = −y the material angle
      // from d1 toward d2 is −ψ.
      const double psi = spec_.chamber_rotation[m] + c * 2.0 * std::numbers::pi / 3.0;
      actuation.chamber_angles[chamber_index(m, c)] = -psi;
    }
  }
  actuation.gains = gains_;
  actuation.regulators = spec_.regulators;
  actuation.regulators.disabled = disabled_chambers(spec_.scenario, spec_.damaged_chamber);
  actuation.hysteresis_width_bar = spec_.effects.hysteresis ? spec_.effects.hysteresis_width : 0.0;

  rod_.add<FixedEnd>();
  rod_.add<Gravity>(gravity);
  modules_ = &rod_.add<PneumaticModules>(actuation);
  if (spec_.effects.imbalance) rod_.add<MassEccentricity>(offsets, gravity);
  rod_.add<AnalyticalLinearDamping>(spec_.translational_damping, spec_.rotational_damping);

  SnapshotWriter out(straight_at_rest_);
  rod_.save_state(out);
  capture_.restart(true_tip_positions());
}

bool PneumaticArm::begin_trial(std::optional<uint64_t> seed) {
  if (seed) {
    drift_rng_ = Rng(*seed, kDriftStream);
    elasticity_rng_ = Rng(*seed, kElasticityStream);
    capture_.set_rng(Rng(*seed, kSensorStream));
    drift_angles_.setZero();
  }
  SnapshotReader straight(straight_at_rest_);
  rod_.load_state(straight);
  if (spec_.effects.drift) step_drift();
  modules_->set_curvature_bias(drift_angles_ / spec_.module_length());

  const bool drift_free = drift_angles_.isZero(0.0);
  bool finite = true;
  if (drift_free && !settled_.empty()) {
    SnapshotReader settled(settled_);
    rod_.load_state(settled);
  } else {
    const int steps = static_cast<int>(std::lround(spec_.settle_time / spec_.time_step));
    finite = rod_.advance(steps);
    if (drift_free && finite) {
      SnapshotWriter out(settled_);
      rod_.save_state(out);
    }
  }
  // At zero pressure the elasticity moves nothing, so it is set after settling (a settled
  // snapshot holds the modules' gains of the trial that made it).
  if (spec_.effects.elasticity) {
    draw_elasticity();
  } else {
    modules_->set_module_gains(Eigen::Matrix<double, 1, kModules>::Ones());
  }
  trial_start_ = rod_.time();
  capture_.restart(true_tip_positions());
  return finite;
}

void PneumaticArm::draw_elasticity() {
  Eigen::Matrix<double, 1, kModules> gains;
  for (int m = 0; m < kModules; ++m) {
    const double xi = std::clamp(elasticity_rng_.normal(), -2.0, 2.0);
    gains[m] = 1.0 + spec_.effects.elasticity_sigma * xi;
  }
  modules_->set_module_gains(gains);
}

void PneumaticArm::step_drift() {
  const double lever_norm =
      std::sqrt(kTipLevers[0] * kTipLevers[0] + kTipLevers[1] * kTipLevers[1] +
                kTipLevers[2] * kTipLevers[2]);
  const double sigma = spec_.effects.drift_step / (spec_.module_length() * lever_norm);
  for (int m = 0; m < kModules; ++m) {
    for (int r = 0; r < 2; ++r) drift_angles_(r, m) += sigma * drift_rng_.normal();
  }
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  for (int m = 0; m < kModules; ++m) {
    shift += kTipLevers[m] * spec_.module_length() * drift_angles_.col(m);
  }
  const double estimate = shift.norm();
  if (estimate > spec_.effects.drift_cap) drift_angles_ *= spec_.effects.drift_cap / estimate;
}

bool PneumaticArm::advance_samples(int samples) {
  for (int s = 0; s < samples; ++s) {
    if (!rod_.advance(steps_per_sample_)) return false;
    capture_.sample(true_tip_positions());
  }
  return true;
}

TipPositions PneumaticArm::true_tip_positions() const {
  TipPositions tips;
  for (int m = 0; m < kModules; ++m) {
    tips.col(m) = rod_.state().positions.col((m + 1) * spec_.elements_per_module);
  }
  return tips;
}

void PneumaticArm::save_state(SnapshotWriter& out) const {
  out.section("PneumaticArm");
  rod_.save_state(out);
  capture_.save_state(out);
  out.put(drift_rng_);
  out.put(elasticity_rng_);
  out.put_matrix(drift_angles_);
  out.put(trial_start_);
}

void PneumaticArm::load_state(SnapshotReader& in) {
  in.section("PneumaticArm");
  Snapshot rod_before;
  SnapshotWriter rod_writer(rod_before);
  rod_.save_state(rod_writer);
  rod_.load_state(in);
  try {
    MotionCapture capture = capture_;
    capture.load_state(in);
    Rng drift_rng = drift_rng_;
    in.get(drift_rng);
    Rng elasticity_rng = elasticity_rng_;
    in.get(elasticity_rng);
    Eigen::Matrix<double, 2, kModules> drift_angles;
    in.get_matrix(drift_angles);
    const double trial_start = in.get_double();
    capture_ = std::move(capture);
    drift_rng_ = drift_rng;
    elasticity_rng_ = elasticity_rng;
    drift_angles_ = drift_angles;
    trial_start_ = trial_start;
  } catch (...) {
    SnapshotReader restore(rod_before);
    rod_.load_state(restore);
    throw;
  }
}

}  // namespace tendril::physics::pneumatic
