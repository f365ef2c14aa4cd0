#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"
#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_part.hpp"
#include "tendril/physics/rod/rod_spec.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// Counts of an implicit rod's work since it was built.
struct NewtonStatistics {
  int64_t steps = 0;           // steps taken, halves of failed steps included
  int64_t iterations = 0;      // Newton iterations (one load evaluation and one solve each)
  int64_t factorizations = 0;  // Newton matrices assembled and factorized
  int64_t halvings = 0;        // failed steps taken again as two halves
};

// Newton's method failed in an implicit step; the rod is back at the step's start.
class NewtonFailure : public Error {
 public:
  using Error::Error;
};

// Implicit steps of a Cosserat rod: backward Euler or BDF2 (RodIntegrator) on the rates at the
// end of the step, with Newton's method on the rod's own Jacobian (RodJacobian).
//
// A step of length h from (x, Q, v, ω) solves for v₊ (lab frame) and ω₊ (material frame)
//   x₊ = x + β Δx₋ + γh v₊,          Q₊ = exp(−[β Δθ₋ + γh ω₊]×) Q,
//   m (v₊ − v̂) = γh F(x₊, Q₊, v₊, ω₊),   (J/e)(ω₊ − ω̂) = γh T(x₊, Q₊, v₊, ω₊),
// with F and T every load of the rod (internal, parts, contact, damping) at the end of the step
// and v̂ = v + β (v − v₋), ω̂ = ω + β (ω − ω₋). Backward Euler: β = 0, γ = 1. BDF2 with the
// ratio r = h/h₋ to the previous step (whose increments Δx₋, Δθ₋ and start rates v₋, ω₋ it
// keeps): β = r²/(1 + 2r), γ = (1 + r)/(1 + 2r) — at a constant step x₊ = (4x − x₋)/3 + ⅔ h v₊
// (Hairer & Wanner, Solving ODEs II, §III.5); its first step, and the first after the state was
// set from outside, is backward Euler.
//
// Newton starts from the rates extrapolated from the last two steps' (v₊ = v + (h/h₋)(v − v₋)),
// or, on a first step, from the rates at its start (the configuration the rates alone would
// reach, as the lattice's ImplicitSolver does). It keeps the last factorized
// Newton matrix, from this step or an earlier one, while the updates contract fast (the chord
// method, as Hairer & Wanner's RADAU5 keeps its Jacobian across steps); when the contraction
// rate θ = |Δ_k|/|Δ_{k−1}| exceeds 0.2, or the step's length γh changed, it assembles and
// factorizes the matrix anew at the current iterate. The step has
// converged when θ/(1 − θ)|Δ_k| — the change still to come, for a linear contraction (Hairer &
// Wanner, §IV.8) — or the first update itself is below NewtonSettings::tolerance, |Δ| being the
// largest change of a node (relative to the rod's length) or of an element's rotation
// (radians). An iterate whose update is not clearly smaller than the one before is refused
// (Deuflhard's natural monotonicity test): the matrix is refactorized at the iterate before
// it, and if that matrix was fresh already, the update is halved (contact switching on and off
// between iterates can make full Newton steps cycle). A step that does not converge in
// max_iterations, or meets a singular matrix or non-finite loads, raises NewtonFailure (a
// tendril::Error); the rod is then put back where the step started, its parts included, and
// the Rod may take the step again in halves (NewtonSettings::max_halvings).
class ImplicitStepper {
 public:
  ImplicitStepper(const RodModel& model, RodIntegrator integrator, const NewtonSettings& newton);

  // Sizes the Newton matrix for the rod's parts (contact widens its band).
  void configure(const RodModel& model, const PartsByStage& parts);
  // Advances the rod by one step of `h` seconds; raises NewtonFailure.
  void step(const RodModel& model, RodState& state, const PartsByStage& parts, double h);
  // Forgets the previous step (BDF2 starts anew with backward Euler) and the Newton matrix.
  void reset_history() {
    has_history_ = false;
    matrix_step_ = 0.0;
  }

  // The previous step, which BDF2 builds on, and the Newton matrix kept for the next step;
  // load_state reads everything before changing anything.
  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

  RodIntegrator integrator() const { return integrator_; }
  const NewtonSettings& newton() const { return newton_; }
  const NewtonStatistics& statistics() const { return statistics_; }
  void count_halving() { ++statistics_.halvings; }
  // The Newton matrix as last assembled (tests compare it with finite differences; it is
  // factorized in place, so call assemble_for_test first).
  const RodJacobian& jacobian() const { return jacobian_; }
  // Assembles the Newton matrix at the state as it is, for a step of effective length γh,
  // without factorizing it (tests). The state's loads must be current.
  void assemble_for_test(const RodModel& model, const RodState& state, const PartsByStage& parts,
                         double effective_step);

 private:
  void set_configuration(const RodModel& model, RodState& state, const PartsByStage& parts);
  void evaluate_loads(const RodModel& model, RodState& state, const PartsByStage& parts);
  void assemble(const RodModel& model, const RodState& state, const PartsByStage& parts);
  void compute_residual(const RodModel& model, const RodState& state);
  double scaled_norm(const RodModel& model, const Eigen::VectorXd& update) const;
  void set_rates(const RodModel& model, RodState& state, double damping) const;
  void add_update(const RodModel& model, RodState& state) const;
  [[noreturn]] void fail(const RodModel& model, RodState& state, const PartsByStage& parts,
                         const std::string& what);

  RodIntegrator integrator_;
  NewtonSettings newton_;
  RodJacobian jacobian_;
  NewtonStatistics statistics_;
  double length_scale_;  // the rod's rest length, m

  // This step: its start, the scheme's coefficients and increments.
  Vectors start_positions_, start_velocities_, start_angular_velocities_;
  Frames start_directors_;
  double start_time_ = 0.0;
  double effective_step_ = 0.0;        // γh
  Vectors position_offsets_;           // β Δx₋ per node
  Vectors rotation_offsets_;           // β Δθ₋ per element
  Vectors target_velocities_;          // v̂
  Vectors target_angular_velocities_;  // ω̂
  Eigen::VectorXd residual_;           // then the Newton update, in RodJacobian's order
  // The last accepted iterate's rates and its Newton update.
  Vectors accepted_velocities_, accepted_angular_velocities_;
  Eigen::VectorXd update_;
  Snapshot parts_at_start_;  // the parts' state before the step, to undo a failure

  // The factorized Newton matrix is for steps of this effective length γh (0: none).
  double matrix_step_ = 0.0;

  // The previous step (BDF2).
  bool has_history_ = false;
  double previous_step_ = 0.0;
  Vectors previous_position_increments_, previous_rotation_increments_;
  Vectors previous_velocities_, previous_angular_velocities_;
};

}  // namespace tendril::physics
