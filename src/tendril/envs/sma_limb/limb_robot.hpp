#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"

namespace tendril::envs::sma_limb {

// One reading of the limb's bend sensor as the firmware streams it (seed 001, Ch. 3): its time
// stamp and the two bend angles, raw (the sensor's zero offsets included).
struct LimbSample {
  double time_s = 0.0;                                   // since the robot was reset
  Eigen::Vector2d angles_deg = Eigen::Vector2d::Zero();  // θx, θy; NaN if the robot failed
};

// The SMA limb at the level of its firmware: four PWM channels (8-bit duty of 11.1 V, order
// +x, −x, +y, −y; at most one coil of each antagonistic pair on) and a bend sensor read every
// 55–75 ms. Everything above this interface — the throttle environment, calibration, data
// collection — sees only these inputs and outputs, so a bridge to the real Arduino can take the
// twin's place.
class LimbRobot {
 public:
  virtual ~LimbRobot() = default;

  // Brings the robot to rest (cooled to ambient, straight; coil wear stays) and returns its
  // first reading, at time 0. `seed` seeds whatever is random in a simulated robot.
  virtual LimbSample reset(uint64_t seed) = 0;
  // Drives the coils with `pwm` until the next reading arrives, and returns that reading.
  // Raises Error for PWM outside 0–255 or both coils of a pair on.
  virtual LimbSample command(const std::array<int, 4>& pwm) = 0;
  // One line for data-set metadata ("SMA limb twin, stiff (40A) ...").
  virtual std::string description() const = 0;

  // Optional capabilities of simulated robots; the defaults say the robot lacks them.
  virtual bool supports_snapshots() const { return false; }
  virtual void save_state(SnapshotWriter& out) const;
  virtual void load_state(SnapshotReader& in);
  virtual bool describe_scene(Scene& /*scene*/) const { return false; }
  // A push on the tip (N, along the limb's x and y) for `duration_s`; a hand on a real robot.
  virtual void push(const Eigen::Vector2d& force_n, double duration_s);
};

}  // namespace tendril::envs::sma_limb
