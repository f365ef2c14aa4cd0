#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rod/rod.hpp"
#include "tendril/physics/twins/sma/bend_sensor.hpp"
#include "tendril/physics/twins/sma/sma_actuator.hpp"
#include "tendril/physics/twins/sma/sma_limb_spec.hpp"
#include "tendril/physics/twins/sma/tip_push.hpp"

namespace tendril::physics {

// The physics twin of the thesis' SMA limb (seed 001): a clamped Cosserat rod of silicone under
// gravity, its four SMA coils (SmaActuator), a push on its tip (TipPush) and its bend sensor
// (BendSensor), advanced from one sensor reading to the next — the hardware's own rhythm.
//
//   SmaLimb limb(SmaLimbSpec::stiff(), seed);
//   limb.set_pwm({38, 0, 0, 0});             // +x coil at 38/255
//   BendReading r = limb.next_reading();     // ≈ 55–75 ms later
//
// Everything that evolves (rod, coil temperatures and phases, degradation, push, sensor clock
// and noise stream) is part of the rod's snapshot, so save_state/load_state restore it exactly.
class SmaLimb {
 public:
  // Builds the limb at rest at ambient temperature and takes the reading at time 0. `seed`
  // seeds the sensor's noise and timing.
  SmaLimb(const SmaLimbSpec& spec, uint64_t seed);

  SmaLimb(SmaLimb&&) = default;
  SmaLimb& operator=(SmaLimb&&) = default;

  // The four coils' PWM (0–255; +x, −x, +y, −y) from now on (SmaActuator::set_pwm's checks).
  void set_pwm(const std::array<int, 4>& pwm);
  const std::array<int, 4>& pwm() const { return actuator_->pwm(); }
  // Advances to the sensor's next reading and returns it; after the rod's state became
  // non-finite, readings are NaN and the limb no longer advances.
  BendReading next_reading();
  const BendReading& last_reading() const { return last_reading_; }
  // When the next reading is due (ms of the limb's clock): what an emulated sensor needs to
  // raise its data-ready line at the right moment.
  int64_t next_reading_ms() const { return sensor_->next_sample_ms(); }
  bool finite() const { return finite_; }
  // Pushes the tip with `force` (lab frame, N) for `duration` seconds from now.
  void push(const Eigen::Vector3d& force, double duration);

  const SmaLimbSpec& spec() const { return spec_; }
  double time() const { return 1e-3 * static_cast<double>(steps_) / spec_.steps_per_millisecond; }
  // The tip's true bend angles (deg, no sensor error or offset).
  Eigen::Vector2d true_angles_deg() const { return sensor_->true_angles_deg(rod_.state()); }
  const SmaCoilState& coil(int index) const { return actuator_->coil(index); }
  double tension(int index) const { return actuator_->tension(index); }
  const Rod& rod() const { return rod_; }

  void save_state(SnapshotWriter& out) const;
  // Raises Error on a snapshot of another limb; the limb is then unchanged.
  void load_state(SnapshotReader& in);

  // The limb (rod), its mount, the four coils (paths, role "sma_coil") and read-outs as values.
  void describe(Scene& scene) const;

 private:
  SmaLimbSpec spec_;
  Rod rod_;
  SmaActuator* actuator_ = nullptr;
  TipPush* push_ = nullptr;
  BendSensor* sensor_ = nullptr;
  int64_t steps_ = 0;
  BendReading last_reading_;
  bool finite_ = true;
};

}  // namespace tendril::physics
