#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"

namespace tendril::envs::pneumatic {

// PneumaticArm/Robot-v0: the three-module pneumatic arm of seed 002 as a robot — the inputs and
// outputs of the hardware, nothing of a task — here with the twin behind it. A hardware bridge
// would implement the same interface.
//
//   action       the 9 pressure commands, bar, chamber 3 m + c (module m, chamber c, from 0);
//                Box [0, ceiling]. The regulators clamp whatever arrives to [0, 4] bar and then
//                to the 1.5 bar safety ceiling; a wrong size or a non-finite value is an Error.
//   observation  the 3 module-tip positions from the motion capture, mm, robot frame (origin on
//                the base plane, z negative downward): module 1 x y z, module 2, module 3; with
//                `observe_pressures: true` then the 9 chamber pressures the regulators measure,
//                bar. The capture samples at 100 Hz; a step returns the newest sample (or the one
//                `sensor_latency_s` old).
//   step         holds the commands for `control_period_s` (default 0.1 s: the paper's 10 Hz).
//   reset        begins a trial (PneumaticArm::begin_trial): rest pose, vented chambers, one step
//                of the resting drift; with a seed the drift and the sensor noise restart from it.
//   reward       0; terminated only if the twin's state became non-finite (info "nan" = 1).
// Info: "time_s" (since the trial began), "nan".
//
// Params: those of arm_spec_from (arm_params.hpp), plus control_period_s and observe_pressures.
class RobotEnv : public Env {
 public:
  static constexpr const char* kId = "PneumaticArm/Robot-v0";
  static constexpr int64_t kTrialSteps = 150;  // registered time limit (seed 002, Fig. 8)
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  RobotEnv(const physics::pneumatic::PneumaticArmSpec& spec, double control_period,
           bool observe_pressures);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The arm's centreline and radii, its three module tips (role "marker"), the pressures.
  bool describe_scene(Scene& scene) const override;

  const physics::pneumatic::PneumaticArm& arm() const { return arm_; }
  double control_period() const { return control_period_; }
  bool observes_pressures() const { return observe_pressures_; }

 private:
  Observation observe() const;

  physics::pneumatic::PneumaticArm arm_;
  double control_period_;
  int samples_per_step_;
  bool observe_pressures_;
  Space observation_space_, action_space_;
  Observation last_observation_;
  Info info_;
};

}  // namespace tendril::envs::pneumatic
