#pragma once

#include <Eigen/Core>
#include <optional>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::envs::pneumatic {

// The module-tip positions of the pneumatic arm as one vector: module 1 x y z, module 2,
// module 3; mm, robot frame (z negative downward).
using TipVector = Eigen::Matrix<double, 9, 1>;
using physics::pneumatic::ChamberVector;

// What the reaching task steps (seed 002 §IV-A): the arm's response to pressures, one control
// period at a time. Behind it stands the robot interface (the twin today, hardware tomorrow:
// RobotDynamics) or a learned model of the arm (the LSTM of eq. (1), from the learned-dynamics
// layer), so that one task definition serves training in the model and evaluation on the arm.
class ArmDynamics {
 public:
  virtual ~ArmDynamics() = default;

  // Starts an episode with every chamber vented and returns the tips at rest; a seed restarts
  // the source's random streams.
  virtual TipVector reset(std::optional<uint64_t> seed) = 0;
  // Holds `pressures_bar` (each within [0, 1.5]) for one control period and returns the tips.
  virtual TipVector step(const ChamberVector& pressures_bar) = 0;
  // Whether the last reset/step kept a finite state.
  virtual bool finite() const { return true; }

  // As Env's: snapshots of everything that evolves, and what a viewer draws (lab frame, m).
  virtual bool supports_snapshots() const { return false; }
  virtual void save_state(SnapshotWriter& out) const;
  virtual void load_state(SnapshotReader& in);
  virtual void describe_scene(Scene& /*scene*/) const {}
};

}  // namespace tendril::envs::pneumatic
