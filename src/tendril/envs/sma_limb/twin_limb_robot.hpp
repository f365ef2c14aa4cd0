#pragma once

#include <memory>

#include "tendril/envs/sma_limb/limb_robot.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace tendril::envs::sma_limb {

// The LimbRobot interface over the physics twin (physics::SmaLimb). A reset rebuilds the limb
// at rest with the coils as worn as they were: over-heating damage, as on the real robot, lasts
// for the robot's life (this object's).
class TwinLimbRobot final : public LimbRobot {
 public:
  explicit TwinLimbRobot(physics::SmaLimbSpec spec);

  LimbSample reset(uint64_t seed) override;
  LimbSample command(const std::array<int, 4>& pwm) override;
  std::string description() const override;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  bool describe_scene(Scene& scene) const override;
  void push(const Eigen::Vector2d& force_n, double duration_s) override;

  // The twin itself, for tests that compare against its true state.
  const physics::SmaLimb& limb() const { return *limb_; }

 private:
  LimbSample sample(const physics::BendReading& reading) const;

  physics::SmaLimbSpec spec_;
  std::unique_ptr<physics::SmaLimb> limb_;
};

}  // namespace tendril::envs::sma_limb
