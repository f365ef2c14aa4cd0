#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"

namespace tendril::envs::tendon_arm {

// What the reach task steps: the arm's tip response to tendon tensions, one control period at a
// time. Behind it stands the robot (RobotPlant: TendonArm/Robot-v0, its twin today, a bridge
// tomorrow) or a learned model of it (ModelPlant), so one task definition serves both.
class Plant {
 public:
  virtual ~Plant() = default;

  virtual int tendons() const = 0;
  virtual double max_tension() const = 0;  // N
  // The arm at rest, tendons slack; returns the tip (m, lab frame).
  virtual Eigen::Vector3d reset(std::optional<uint64_t> seed) = 0;
  // Holds `tensions` (N, each within [0, max_tension]) for one control period; returns the tip.
  virtual Eigen::Vector3d step(const Eigen::VectorXd& tensions) = 0;
  // Whether the last reset/step kept a finite state.
  virtual bool finite() const = 0;

  // As Env's: everything that evolves, and what a viewer draws (lab frame, m).
  virtual bool supports_snapshots() const = 0;
  virtual void save_state(SnapshotWriter& out) const = 0;
  virtual void load_state(SnapshotReader& in) = 0;
  virtual void describe_scene(Scene& scene) const = 0;
};

}  // namespace tendril::envs::tendon_arm
