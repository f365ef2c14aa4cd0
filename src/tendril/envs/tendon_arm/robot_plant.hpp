#pragma once

#include <memory>

#include "tendril/core/env.hpp"
#include "tendril/envs/tendon_arm/plant.hpp"

namespace tendril::envs::tendon_arm {

// The plant through the robot interface: an Env with TendonArm/Robot-v0's action (tensions, N)
// and the tip (m) first in its observation. Knows nothing of what stands behind the interface.
class RobotPlant final : public Plant {
 public:
  // Raises Error unless `robot` takes a box of tensions and observes at least 3 values.
  explicit RobotPlant(std::unique_ptr<Env> robot);

  int tendons() const override { return robot_->action_space().size(); }
  double max_tension() const override { return robot_->action_space().high().maxCoeff(); }
  Eigen::Vector3d reset(std::optional<uint64_t> seed) override;
  Eigen::Vector3d step(const Eigen::VectorXd& tensions) override;
  bool finite() const override { return finite_; }
  bool supports_snapshots() const override { return robot_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  void describe_scene(Scene& scene) const override { robot_->describe_scene(scene); }

  Env& robot() { return *robot_; }

 private:
  std::unique_ptr<Env> robot_;
  Action action_;
  bool finite_ = true;
};

}  // namespace tendril::envs::tendon_arm
