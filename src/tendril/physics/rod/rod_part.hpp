#pragma once

#include <cstdint>
#include <vector>

#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

class RodJacobian;

// The stages of one position-Verlet step at which a part acts, in the order the stepper runs
// them (Gazzola et al. 2018, §3.3; PyElastica's symplectic stepper):
//   half kinematic step → kConstrainValues → kStartStep → internal loads → kLoads → kContact →
//   dynamic step → kConstrainRates → kDampRates → half kinematic step → kConstrainValues.
// An implicit step (ImplicitStepper) runs kStartStep once, at the end of the step, and then, for
// every Newton iterate of the end-of-step configuration: kConstrainValues, internal loads,
// kLoads, the damping of kDampRates parts as loads, and kContact; kConstrainRates parts fix
// unknowns of the Newton system instead of resetting rates.
enum RodStage : uint32_t {
  kConstrainValues = 1u << 0,  // reset constrained positions / directors
  kLoads = 1u << 1,            // add external forces and couples (forcing, force-like damping)
  kContact = 1u << 2,          // add wall responses; sees internal + external loads
  kConstrainRates = 1u << 3,   // reset constrained velocities / angular velocities
  kDampRates = 1u << 4,        // scale rates after the dynamic step (analytical damping)
  kStartStep = 1u << 5,        // advance the part's own state (once per step, before loads)
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
  // Advances what the part carries from step to step (rate-limited control points, regulators,
  // coil temperatures) over a step of `step` seconds, to the time at which the step's loads act
  // (state.time). Loads must then depend only on that state and the configuration, since an
  // implicit step evaluates them several times.
  virtual void start_step(const RodModel& /*model*/, RodState& /*state*/, double /*step*/) {}
  virtual void add_loads(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void add_contact_loads(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void constrain_rates(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void damp_rates(const RodModel& /*model*/, RodState& /*state*/) {}

  // Implicit stepping. A kLoads or kContact part whose loads depend on the configuration or the
  // rates adds their derivatives here (RodJacobian); if it leaves some out, Newton's method
  // converges more slowly or fails with an Error, never silently. kDampRates parts add their
  // damping as loads (forces −c v, torques −c ω) with add_damping_loads, and its derivatives
  // here. kConstrainRates parts name the rates they hold at zero with fix_rates.
  virtual void add_load_derivatives(const RodModel& /*model*/, const RodState& /*state*/,
                                    RodJacobian& /*jacobian*/) const {}
  virtual void add_damping_loads(const RodModel& /*model*/, RodState& /*state*/) {}
  virtual void fix_rates(const RodModel& /*model*/, RodJacobian& /*jacobian*/) const {}

  // A part whose state evolves in time (rate-limited control points, coil temperatures,
  // chamber pressures, sensor delay lines) writes all of it here and reads it back exactly, so
  // that Rod::save_state/load_state capture the whole simulation. Stateless parts keep the
  // defaults. load_state reads everything before it changes anything.
  virtual void save_state(SnapshotWriter& /*out*/) const {}
  virtual void load_state(SnapshotReader& /*in*/) {}
};

// A rod's parts by the stages they act at, each list in attachment order.
struct PartsByStage {
  std::vector<RodPart*> constrain_values, start_step, loads, contact, constrain_rates, damp_rates;

  void add(RodPart* part) {
    const uint32_t stages = part->stages();
    if (stages & kConstrainValues) constrain_values.push_back(part);
    if (stages & kStartStep) start_step.push_back(part);
    if (stages & kLoads) loads.push_back(part);
    if (stages & kContact) contact.push_back(part);
    if (stages & kConstrainRates) constrain_rates.push_back(part);
    if (stages & kDampRates) damp_rates.push_back(part);
  }
};

}  // namespace tendril::physics
