#pragma once

#include <Eigen/Core>

#include "tendril/core/snapshot.hpp"
#include "tendril/physics/lattice/lattice_model.hpp"

namespace tendril::physics {

// An external load on a lattice (a couple, a tip force, an actuator), attached to a Lattice
// like a rod part: adding an actuator is a new load, never an edit of the integrators. Loads
// are evaluated once per time step and held over it: the symplectic step at the positions it
// starts from, the implicit steps at the predicted end of the step (where their Newton solve
// starts).
class LatticeLoad {
 public:
  virtual ~LatticeLoad() = default;

  // Called once when attached; validates node indices and sizes buffers. Raises
  // tendril::Error on a load that does not fit the lattice.
  virtual void attach(const LatticeModel& /*model*/) {}

  // Adds this load's forces (N, lab frame) at `positions` (m) to `forces`. Must not allocate.
  virtual void add_forces(const LatticeModel& model, const Eigen::Matrix2Xd& positions,
                          Eigen::Matrix2Xd& forces) const = 0;

  // A load whose inputs evolve in time (set torques, ramps) writes them here and reads them
  // back exactly; load_state reads everything before it changes anything.
  virtual void save_state(SnapshotWriter& /*out*/) const {}
  virtual void load_state(SnapshotReader& /*in*/) {}
};

}  // namespace tendril::physics
