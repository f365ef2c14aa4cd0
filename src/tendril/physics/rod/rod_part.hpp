#pragma once

#include <cstdint>

#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// The stages of one position-Verlet step at which a part acts, in the order the stepper runs
// them (Gazzola et al. 2018, §3.3; PyElastica's symplectic stepper):
//   half kinematic step → kConstrainValues → internal loads → kLoads → kContact →
//   dynamic step → kConstrainRates → kDampRates → half kinematic step → kConstrainValues.
enum RodStage : uint32_t {
  kConstrainValues = 1u << 0,  // reset constrained positions / directors
  kLoads = 1u << 1,            // add external forces and couples (forcing, force-like damping)
  kContact = 1u << 2,          // add wall responses; sees internal + external loads
  kConstrainRates = 1u << 3,   // reset constrained velocities / angular velocities
  kDampRates = 1u << 4,        // scale rates after the dynamic step (analytical damping)
};

// A small type attached to a rod (boundary condition, load, damping, contact, actuator).
// Adding a new kind of part never edits the stepper: a part declares its stages and implements
// the matching hooks. Hooks run on the hot path and must not allocate.
class RodPart {
 public:
  virtual ~RodPart() = default;

  // Bitwise OR of the RodStage values this part acts at.
  virtual uint32_t stages() const = 0;

  // Called once when the part is attached; validates indices, captures rest values, sizes
  // buffers. Raises tendril::Error on a part that does not fit the rod.
  virtual void attach(const RodModel& /*model*/, const RodState& /*state*/) {}

  virtual void constrain_values(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void add_loads(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void add_contact_loads(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void constrain_rates(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void damp_rates(const RodModel& /*model*/, RodState& /*state*/) {}

  // A part whose state evolves in time (rate-limited control points, coil temperatures,
  // chamber pressures, sensor delay lines) writes all of it here and reads it back exactly, so
  // that Rod::save_state/load_state capture the whole simulation. Stateless parts keep the
  // defaults. load_state reads everything before it changes anything.
  virtual void save_state(SnapshotWriter& /*out*/) const {}
  virtual void load_state(SnapshotReader& /*in*/) {}
};

}  // namespace tendril::physics
