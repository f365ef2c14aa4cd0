#pragma once

#include <Eigen/Core>
#include <optional>

#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rod/rod.hpp"
#include "tendril/physics/twins/pneumatic/motion_capture.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm_spec.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_modules.hpp"

namespace tendril::physics::pneumatic {

// A twin of the three-module pneumatic arm of seed 002: one Cosserat rod of three modules
// hanging from a clamped base under gravity, its nine chambers (PneumaticModules: regulators
// with the safety ceiling, fill/vent lag, hysteresis, damage), an optional imbalance
// (MassEccentricity and chamber gains), resting-position drift between trials, and the motion
// capture that samples the three module tips at 100 Hz.
//
// Time advances in whole sensor samples. The twin holds its own random streams: the drift walk,
// the elasticity of the day and the sensor noise, all reseeded by begin_trial(seed) — a trial
// begun with the same seed from the same configuration repeats exactly.
class PneumaticArm {
 public:
  explicit PneumaticArm(const PneumaticArmSpec& spec);

  PneumaticArm(const PneumaticArm&) = delete;
  PneumaticArm& operator=(const PneumaticArm&) = delete;

  // Starts a trial: the rod straight at rest, chambers vented, hysteresis cleared; the resting
  // drift takes one step of its walk (with a seed: the walk and the sensor restart from that
  // seed, the drift from zero); the arm then settles for settle_time at zero pressure and the
  // sensor restarts from that state; the modules then take the trial's elasticity. Returns false
  // if the state became non-finite.
  bool begin_trial(std::optional<uint64_t> seed = std::nullopt);

  // Pressure commands, bar, any finite values (Error otherwise); the regulators clamp them.
  void set_commands(const ChamberVector& commands_bar) { modules_->set_commands(commands_bar); }
  // Advances `samples` sensor periods, sampling the motion capture after each. Returns false
  // (and stops) if the state became non-finite.
  bool advance_samples(int samples);

  // The true module-tip positions (lab frame, m; columns = modules 1, 2, 3), and what the
  // motion capture reports to a controller now (noisy, delayed).
  TipPositions true_tip_positions() const;
  const TipPositions& measured_tip_positions() const { return capture_.read(); }

  const ChamberVector& commands() const { return modules_->regulators().commands(); }
  const ChamberVector& pressures() const { return modules_->regulators().pressures(); }
  const ChamberVector& effective_pressures() const { return modules_->effective_pressures(); }
  // The drift walk's module bend angles (rad; material d1, d2 components).
  const Eigen::Matrix<double, 2, kModules>& drift_angles() const { return drift_angles_; }
  // The instance's chamber gains (all 1 without imbalance).
  const ChamberVector& chamber_gains() const { return gains_; }
  // This trial's elasticity factor per module (all 1 without the effect).
  const Eigen::Matrix<double, 1, kModules>& module_gains() const {
    return modules_->module_gains();
  }

  const Rod& rod() const { return rod_; }
  const PneumaticArmSpec& spec() const { return spec_; }
  double time() const { return rod_.time() - trial_start_; }  // s since the trial began
  double sample_period() const { return spec_.sensor.sample_period; }

  // The whole evolving state: rod with its parts, drift walk, random streams, sensor.
  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  void step_drift();
  void draw_elasticity();

  PneumaticArmSpec spec_;
  ChamberVector gains_ = ChamberVector::Ones();
  Rod rod_;
  PneumaticModules* modules_ = nullptr;  // owned by rod_
  Snapshot straight_at_rest_;            // rod_ as built
  Snapshot settled_;                     // rod_ after settling without drift (cached)
  MotionCapture capture_;
  Rng drift_rng_;
  Rng elasticity_rng_;
  Eigen::Matrix<double, 2, kModules> drift_angles_ = Eigen::Matrix<double, 2, kModules>::Zero();
  double trial_start_ = 0.0;
  int steps_per_sample_;
};

}  // namespace tendril::physics::pneumatic
