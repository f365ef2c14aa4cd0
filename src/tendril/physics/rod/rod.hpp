#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "tendril/physics/rod/implicit_stepper.hpp"
#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_part.hpp"
#include "tendril/physics/rod/rod_spec.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

struct RodEnergies {
  double translational_kinetic = 0.0;  // ½ Σ m v²
  double rotational_kinetic = 0.0;     // ½ Σ ωᵀ (J/e) ω
  double shear_stretch = 0.0;          // ½ Σ l̂ (σ − σ̂)ᵀ S (σ − σ̂)
  double bend_twist = 0.0;             // ½ Σ D̂ (κ − κ̂)ᵀ B (κ − κ̂)
  double total() const {
    return translational_kinetic + rotational_kinetic + shear_stretch + bend_twist;
  }
};

// A discrete Cosserat rod (Gazzola et al. 2018) assembled from parts and advanced with a fixed
// time step by position Verlet or, as RodSpec::integrator chooses, implicitly (backward Euler or
// BDF2 with Newton's method; ImplicitStepper). Parameters (RodModel) are immutable after
// construction; the state (RodState) is sized once. Parts are attached declaratively:
//
//   Rod arm(spec);
//   arm.add<FixedEnd>();
//   arm.add<InternalDamping>(30.0);
//   auto& couples = arm.add<ElementCouples>();
//
// Invariant: directors stay orthonormal (rotations are applied by the exponential map).
class Rod {
 public:
  // Builds a straight rod from node 0 at spec.base_position along spec.direction, at rest.
  // Raises tendril::Error naming the first invalid field of `spec`.
  explicit Rod(const RodSpec& spec);

  Rod(const Rod&) = delete;
  Rod& operator=(const Rod&) = delete;
  Rod(Rod&&) = default;
  Rod& operator=(Rod&&) = default;

  // Attaches a part; it acts from the next step on, in attachment order within its stages.
  template <typename Part, typename... Args>
  Part& add(Args&&... args) {
    static_assert(std::is_base_of_v<RodPart, Part>);
    auto part = std::make_unique<Part>(std::forward<Args>(args)...);
    Part& reference = *part;
    attach(std::move(part));
    return reference;
  }
  void attach(std::unique_ptr<RodPart> part);
  // The attached parts in attachment order (e.g. for a RodPool to mirror them).
  const std::vector<std::unique_ptr<RodPart>>& parts() const { return parts_; }

  // Advances `steps` time steps. Returns false if the state became non-finite (NaN or ∞); the
  // rod then stops advancing and keeps returning false until its state is set anew. An implicit
  // step whose Newton iteration fails even in halves (NewtonSettings::max_halvings) raises
  // tendril::Error (NewtonFailure), the rod back at that step's start.
  [[nodiscard]] bool advance(int steps = 1);
  // Implicit rods only: advances `duration` seconds in `steps` equal steps (each of any length,
  // e.g. to land exactly on a sensor's sampling time). Raises Error for a position-Verlet rod.
  [[nodiscard]] bool advance_by(double duration, int steps);
  bool state_is_finite() const;

  const RodModel& model() const { return model_; }
  const RodState& state() const { return state_; }
  // Direct access for set-up and tests (e.g. planting an initial deformation). Call
  // `state_changed()` after editing positions or directors from outside.
  RodState& mutable_state() { return state_; }
  void state_changed();

  // The whole evolving state — configuration, rates, time, the finite flag, every part's own
  // state in attachment order and, for BDF2, the previous step — so that advancing after
  // load_state repeats advancing
  // after save_state bit for bit. load_state raises Error on a snapshot of a rod of another
  // size or with other parts, and then leaves the rod as it was.
  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

  double time() const { return state_.time; }
  double time_step() const { return model_.time_step; }
  RodIntegrator integrator() const { return integrator_; }
  bool is_implicit() const { return implicit_ != nullptr; }
  // Newton's work so far (zero for position Verlet).
  NewtonStatistics newton_statistics() const {
    return implicit_ ? implicit_->statistics() : NewtonStatistics{};
  }
  int n_elements() const { return model_.n_elements; }

  // Read-outs (lab frame unless stated).
  // `count` positions of nodes spread evenly along the rod, both ends included
  // (node round(k·n/(count − 1)) for k = 0 … count − 1), as a 3 × count matrix.
  Eigen::Matrix3Xd sampled_node_positions(int count) const;
  Eigen::Vector3d tip_position() const { return state_.positions.col(model_.n_elements); }
  Eigen::Vector3d tip_velocity() const { return state_.velocities.col(model_.n_elements); }
  // Directors of the last element (rows d1 d2 d3) and the unit quaternion of the rotation whose
  // columns are d1 d2 d3 (material → lab).
  Eigen::Matrix3d tip_directors() const { return state_.director(model_.n_elements - 1); }
  Eigen::Quaterniond tip_quaternion() const;
  // Strains of the current configuration: σ per element, κ per interior Voronoi point.
  const Vectors& shear_strains() const { return state_.shear_strains; }
  const Vectors& curvatures() const { return state_.curvatures; }
  RodEnergies energies() const;

 private:
  void kinematic_step(double h);  // x += h v;  Q ← exp(−h [ω]×) Q
  void dynamic_stage();
  void dynamic_step(double dt);
  bool advance_implicitly(int steps, double step);
  void implicit_step(double step, int halvings);
  void load_state_unchecked(SnapshotReader& in);

  RodModel model_;
  RodState state_;
  RodIntegrator integrator_;
  std::vector<std::unique_ptr<RodPart>> parts_;
  // Parts by stage, so the stepper calls only the hooks a part uses.
  PartsByStage stages_;
  std::unique_ptr<ImplicitStepper> implicit_;  // null for position Verlet
  bool finite_ = true;
};

}  // namespace tendril::physics
