#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/pushable_robot.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/envs/sma_limb/limb_robot.hpp"

namespace tendril::envs::sma_limb {

// SmaLimb/Robot-v0: the thesis' SMA limb as its software saw it (seed 001, §4.1–4.2, Ch. 5).
//
// Action: the throttles (u_x, u_y), Box(2, [−10, 10]); each is rounded to the nearest integer
// and turned into the four coils' PWM by the calibrated 21-level table (LimbCalibration) — as the
// firmware does with the commands it receives (throttle = round(10 · value)). One step holds that
// PWM until the bend sensor's next reading, 55–75 ms later.
// Observation: (θx, θy, t): the reading in degrees, the calibration's zero offsets subtracted,
// and its time stamp in seconds since reset.
// The firmware's safety cut-off: while the latest reading has |θx| ≥ 100° or |θy| ≥ 100°, all
// four coils are off whatever the throttles.
// Reward 0 (the robot has no task); episodes never end by themselves (a task or a TimeLimit
// wrapper decides) except when a simulated robot's state became non-finite (terminated, "nan").
// Info, every step: "time_s" (the reading's time stamp, exact), "u_x", "u_y" (the integer
// throttles applied), "pwm_0" … "pwm_3" (+x, −x, +y, −y as driven during the step), "cutoff"
// (1 when the firmware held the coils off), "nan".
//
// Parameters (`env.params`): limb (stiff | soft; default stiff), seed (default 0; the first
// reset without a seed uses it), tip_mass (kg, default 0; the thesis tried 0.010 and 0.050),
// calibration (required: a file written by `tendril data calibrate`, or `none` — the thesis'
// nominal bounds for the limb and no zero offsets; an Error names the key when it is missing),
// backend (twin | bridge; default twin) and bridge (docs/hardware.md).
class SmaLimbEnv : public Env, public PushableRobot {
 public:
  static constexpr const char* kId = "SmaLimb/Robot-v0";
  static constexpr double kCutoffDeg = 100.0;
  static constexpr double kMaxThrottle = 10.0;
  // The `calibration` value that asks for the nominal table and raw readings.
  static constexpr const char* kUncalibrated = "none";

  SmaLimbEnv(std::unique_ptr<LimbRobot> robot, LimbCalibration calibration, uint64_t seed);
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  bool supports_snapshots() const override { return robot_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  bool describe_scene(Scene& scene) const override;

  const LimbCalibration& calibration() const { return calibration_; }
  const LimbRobot& robot() const { return *robot_; }
  // PushableRobot: a push on the tip (N along the limb's x and y) for `duration_s` — a
  // disturbance for robustness tests; Error if the robot cannot be pushed by software.
  int push_dim() const override { return 2; }
  void push_tip(const Eigen::VectorXd& force_n, double duration_s) override;

 private:
  Observation observe(const LimbSample& sample);

  std::unique_ptr<LimbRobot> robot_;
  LimbCalibration calibration_;
  Space observation_space_, action_space_;
  Rng rng_;
  Eigen::Vector2d angles_deg_ = Eigen::Vector2d::Zero();  // latest reading, offsets removed
  double time_s_ = 0.0;
  bool failed_ = false;
  Info info_;
};

}  // namespace tendril::envs::sma_limb
