#pragma once

#include <memory>

#include "tendril/core/env.hpp"
#include "tendril/envs/pneumatic/arm_dynamics.hpp"

namespace tendril::envs::pneumatic {

// ArmDynamics through the robot interface: an Env with PneumaticArm/Robot-v0's action (9
// pressures, bar) and the tips first in its observation (mm). Knows nothing of what stands
// behind the interface.
class RobotDynamics final : public ArmDynamics {
 public:
  // Raises Error unless `robot` has 9 actions and at least 9 observations.
  explicit RobotDynamics(std::unique_ptr<Env> robot);

  TipVector reset(std::optional<uint64_t> seed) override;
  TipVector step(const ChamberVector& pressures_bar) override;
  bool finite() const override { return finite_; }
  bool supports_snapshots() const override { return robot_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  void describe_scene(Scene& scene) const override { robot_->describe_scene(scene); }

  Env& robot() { return *robot_; }

 private:
  static TipVector tips(const Observation& observation);

  std::unique_ptr<Env> robot_;
  Action action_;
  bool finite_ = true;
};

}  // namespace tendril::envs::pneumatic
