#include "tendril/physics/rod/implicit_stepper.hpp"

#include <cmath>
#include <sstream>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/internal_load_derivatives.hpp"
#include "tendril/physics/rod/internal_loads.hpp"
#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

namespace {

// Refactorize when an update shrinks the previous one by less than this.
constexpr double kSlowContraction = 0.2;
// Give up when even updates damped this much do not contract.
constexpr double kSmallestDamping = 1.0 / 64.0;

}  // namespace

ImplicitStepper::ImplicitStepper(const RodModel& model, RodIntegrator integrator,
                                 const NewtonSettings& newton)
    : integrator_(integrator), newton_(newton), length_scale_(model.rest_lengths.sum()) {
  const int n = model.n_elements, nodes = model.n_nodes();
  start_positions_ = Vectors::Zero(3, nodes);
  start_velocities_ = Vectors::Zero(3, nodes);
  start_angular_velocities_ = Vectors::Zero(3, n);
  start_directors_ = Frames::Zero(9, n);
  position_offsets_ = Vectors::Zero(3, nodes);
  rotation_offsets_ = Vectors::Zero(3, n);
  target_velocities_ = Vectors::Zero(3, nodes);
  target_angular_velocities_ = Vectors::Zero(3, n);
  previous_position_increments_ = Vectors::Zero(3, nodes);
  previous_rotation_increments_ = Vectors::Zero(3, n);
  previous_velocities_ = Vectors::Zero(3, nodes);
  previous_angular_velocities_ = Vectors::Zero(3, n);
  residual_ = Eigen::VectorXd::Zero(6 * n + 3);
  update_ = residual_;
  accepted_velocities_ = Vectors::Zero(3, nodes);
  accepted_angular_velocities_ = Vectors::Zero(3, n);
  jacobian_.resize(model, false);
}

void ImplicitStepper::configure(const RodModel& model, const PartsByStage& parts) {
  const bool with_contact = !parts.contact.empty();
  if (with_contact != (jacobian_.matrix().lower() > 11)) jacobian_.resize(model, with_contact);
}

void ImplicitStepper::set_configuration(const RodModel& model, RodState& state,
                                        const PartsByStage& parts) {
  const double h = effective_step_;
  state.positions = start_positions_ + position_offsets_ + h * state.velocities;
  for (int i = 0; i < model.n_elements; ++i) {
    const Eigen::Vector3d rotation = Eigen::Vector3d(rotation_offsets_.col(i)) +
                                     h * Eigen::Vector3d(state.angular_velocities.col(i));
    Eigen::Matrix3d q;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) q(r, c) = start_directors_(3 * r + c, i);
    }
    state.set_director(i, exp_rotation_minus(rotation) * q);
  }
  for (RodPart* part : parts.constrain_values) part->constrain_values(model, state);
}

void ImplicitStepper::evaluate_loads(const RodModel& model, RodState& state,
                                     const PartsByStage& parts) {
  compute_internal_loads(model, state);
  state.external_forces.setZero();
  state.external_torques.setZero();
  for (RodPart* part : parts.loads) part->add_loads(model, state);
  for (RodPart* part : parts.damp_rates) part->add_damping_loads(model, state);
  for (RodPart* part : parts.contact) part->add_contact_loads(model, state);
}

void ImplicitStepper::assemble(const RodModel& model, const RodState& state,
                               const PartsByStage& parts) {
  jacobian_.begin(effective_step_);
  for (int j = 0; j < model.n_nodes(); ++j) {
    for (int c = 0; c < 3; ++c)
      jacobian_.add_diagonal(RodJacobian::node(j) + c, model.node_masses[j]);
  }
  for (int i = 0; i < model.n_elements; ++i) {
    for (int c = 0; c < 3; ++c) {
      jacobian_.add_diagonal(RodJacobian::element(i) + c,
                             model.inertia(c, i) / state.dilatations[i]);
    }
  }
  add_internal_load_derivatives(model, state, jacobian_);
  for (RodPart* part : parts.loads) part->add_load_derivatives(model, state, jacobian_);
  for (RodPart* part : parts.damp_rates) part->add_load_derivatives(model, state, jacobian_);
  for (RodPart* part : parts.contact) part->add_load_derivatives(model, state, jacobian_);
  for (RodPart* part : parts.constrain_rates) part->fix_rates(model, jacobian_);
  jacobian_.finish(model);
}

// −g = γh (F + F_ext) − m (v₊ − v̂) for the nodes, and likewise with the torques and J/e for the
// elements, in RodJacobian's order.
void ImplicitStepper::compute_residual(const RodModel& model, const RodState& state) {
  const double gh = effective_step_;
  double* r = residual_.data();
  for (int j = 0; j <= model.n_elements; ++j) {
    const double mass = model.node_masses[j];
    for (int c = 0; c < 3; ++c) {
      r[RodJacobian::node(j) + c] =
          gh * (state.internal_forces(c, j) + state.external_forces(c, j)) -
          mass * (state.velocities(c, j) - target_velocities_(c, j));
    }
  }
  for (int i = 0; i < model.n_elements; ++i) {
    const double inverse_dilatation = 1.0 / state.dilatations[i];
    for (int c = 0; c < 3; ++c) {
      r[RodJacobian::element(i) + c] =
          gh * (state.internal_torques(c, i) + state.external_torques(c, i)) -
          model.inertia(c, i) * inverse_dilatation *
              (state.angular_velocities(c, i) - target_angular_velocities_(c, i));
    }
  }
}

// How far an update of the rates moves the configuration over the step: the largest node
// displacement relative to the rod's length, or element rotation in radians.
double ImplicitStepper::scaled_norm(const RodModel& model, const Eigen::VectorXd& update) const {
  double largest_move = 0.0, largest_turn = 0.0;
  for (int j = 0; j <= model.n_elements; ++j) {
    for (int c = 0; c < 3; ++c) {
      largest_move = std::max(largest_move, std::abs(update[RodJacobian::node(j) + c]));
    }
  }
  for (int i = 0; i < model.n_elements; ++i) {
    for (int c = 0; c < 3; ++c) {
      largest_turn = std::max(largest_turn, std::abs(update[RodJacobian::element(i) + c]));
    }
  }
  return effective_step_ * std::max(largest_move / length_scale_, largest_turn);
}

// The rates ← the accepted iterate + damping × its update.
void ImplicitStepper::set_rates(const RodModel& model, RodState& state, double damping) const {
  for (int j = 0; j <= model.n_elements; ++j) {
    for (int c = 0; c < 3; ++c) {
      state.velocities(c, j) =
          accepted_velocities_(c, j) + damping * update_[RodJacobian::node(j) + c];
    }
  }
  for (int i = 0; i < model.n_elements; ++i) {
    for (int c = 0; c < 3; ++c) {
      state.angular_velocities(c, i) =
          accepted_angular_velocities_(c, i) + damping * update_[RodJacobian::element(i) + c];
    }
  }
}

// The rates += the update just solved for (residual_).
void ImplicitStepper::add_update(const RodModel& model, RodState& state) const {
  for (int j = 0; j <= model.n_elements; ++j) {
    for (int c = 0; c < 3; ++c) state.velocities(c, j) += residual_[RodJacobian::node(j) + c];
  }
  for (int i = 0; i < model.n_elements; ++i) {
    for (int c = 0; c < 3; ++c) {
      state.angular_velocities(c, i) += residual_[RodJacobian::element(i) + c];
    }
  }
}

void ImplicitStepper::assemble_for_test(const RodModel& model, const RodState& state,
                                        const PartsByStage& parts, double effective_step) {
  effective_step_ = effective_step;
  assemble(model, state, parts);
}

void ImplicitStepper::step(const RodModel& model, RodState& state, const PartsByStage& parts,
                           double h) {
  // The scheme's coefficients (see the class comment).
  double beta = 0.0, gamma = 1.0;
  if (integrator_ == RodIntegrator::kBdf2 && has_history_) {
    const double ratio = h / previous_step_;
    beta = ratio * ratio / (1.0 + 2.0 * ratio);
    gamma = (1.0 + ratio) / (1.0 + 2.0 * ratio);
  }
  effective_step_ = gamma * h;
  start_positions_ = state.positions;
  start_velocities_ = state.velocities;
  start_directors_ = state.directors;
  start_angular_velocities_ = state.angular_velocities;
  start_time_ = state.time;
  if (beta != 0.0) {
    position_offsets_ = beta * previous_position_increments_;
    rotation_offsets_ = beta * previous_rotation_increments_;
    target_velocities_ = state.velocities + beta * (state.velocities - previous_velocities_);
    target_angular_velocities_ =
        state.angular_velocities + beta * (state.angular_velocities - previous_angular_velocities_);
  } else {
    position_offsets_.setZero();
    rotation_offsets_.setZero();
    target_velocities_ = state.velocities;
    target_angular_velocities_ = state.angular_velocities;
  }

  // Newton starts from the rates extrapolated linearly from the previous step's (the rates at
  // the step's start without a previous step).
  if (has_history_) {
    const double ratio = h / previous_step_;
    state.velocities += ratio * (state.velocities - previous_velocities_);
    state.angular_velocities += ratio * (state.angular_velocities - previous_angular_velocities_);
  }

  parts_at_start_.clear();
  SnapshotWriter out(parts_at_start_);
  for (RodPart* part : parts.start_step) part->save_state(out);
  state.time = start_time_ + h;
  for (RodPart* part : parts.start_step) part->start_step(model, state, h);

  const double gh = effective_step_;
  bool need_matrix = matrix_step_ != gh;
  bool matrix_at_accepted = false;  // the matrix was assembled at the accepted iterate
  bool have_update = false;         // update_ holds the Newton update from the accepted iterate
  double update_norm = 0.0, damping = 1.0;
  bool converged = false;
  int iteration = 0;
  for (; iteration < newton_.max_iterations && !converged; ++iteration) {
    set_configuration(model, state, parts);
    evaluate_loads(model, state, parts);
    compute_residual(model, state);
    if (!residual_.allFinite()) fail(model, state, parts, "the loads became non-finite");
    bool assembled_here = false;
    if (need_matrix) {
      assemble(model, state, parts);
      ++statistics_.factorizations;
      if (!jacobian_.matrix().factorize()) {
        fail(model, state, parts, "the Newton matrix is singular");
      }
      matrix_step_ = gh;
      need_matrix = false;
      assembled_here = true;
    }
    for (int u = 0; u < residual_.size(); ++u) {
      if (jacobian_.is_fixed(u)) residual_[u] = 0.0;
    }
    jacobian_.matrix().solve(residual_.data());  // now the Newton update from this iterate
    const double norm = scaled_norm(model, residual_);
    if (!std::isfinite(norm)) fail(model, state, parts, "the Newton update is not finite");

    if (have_update) {
      const double rate = norm / update_norm;
      // The natural monotonicity test (Deuflhard, Newton Methods for Nonlinear Problems, §3.3):
      // an iterate whose update is not clearly smaller than the one that led to it is refused.
      // Contact switching on and off between iterates makes the loads kinked, where full steps
      // can cycle.
      if (rate >= 1.0 - 0.25 * damping) {
        if (!matrix_at_accepted) {
          need_matrix = true;  // first refactorize at the accepted iterate
          have_update = false;
          set_rates(model, state, 0.0);
          continue;
        }
        damping *= 0.5;
        if (damping < kSmallestDamping) {
          fail(model, state, parts, "Newton's method does not contract even with damped updates");
        }
        set_rates(model, state, damping);
        continue;
      }
      if (damping == 1.0 && rate / (1.0 - rate) * norm <= newton_.tolerance) {
        add_update(model, state);
        converged = true;
        continue;
      }
      if (rate > kSlowContraction && !assembled_here) need_matrix = true;
    } else if (norm <= newton_.tolerance) {
      add_update(model, state);
      converged = true;
      continue;
    }
    // Accept this iterate and take (a part of) its update.
    accepted_velocities_ = state.velocities;
    accepted_angular_velocities_ = state.angular_velocities;
    update_ = residual_;
    update_norm = norm;
    matrix_at_accepted = assembled_here;
    have_update = true;
    damping = std::min(1.0, 2.0 * damping);
    set_rates(model, state, damping);
  }
  statistics_.iterations += iteration;
  if (!converged) {
    std::ostringstream what;
    what << "Newton's method did not converge in " << newton_.max_iterations << " iterations";
    fail(model, state, parts, what.str());
  }
  set_configuration(model, state, parts);
  ++statistics_.steps;

  // This step becomes the previous one: its increments and its start rates.
  previous_position_increments_ = position_offsets_ + gh * state.velocities;
  previous_rotation_increments_ = rotation_offsets_ + gh * state.angular_velocities;
  previous_velocities_ = start_velocities_;
  previous_angular_velocities_ = start_angular_velocities_;
  previous_step_ = h;
  has_history_ = true;
}

void ImplicitStepper::fail(const RodModel& model, RodState& state, const PartsByStage& parts,
                           const std::string& what) {
  const double time = state.time, step = state.time - start_time_;
  matrix_step_ = 0.0;  // assembled inside the failed step, perhaps far from its start
  state.positions = start_positions_;
  state.velocities = start_velocities_;
  state.directors = start_directors_;
  state.angular_velocities = start_angular_velocities_;
  state.time = start_time_;
  SnapshotReader in(parts_at_start_);
  for (RodPart* part : parts.start_step) part->load_state(in);
  compute_strains(model, state);
  std::ostringstream message;
  message << what << " in the " << integrator_name(integrator_) << " step from t = " << start_time_
          << " s to " << time << " s (step " << step << " s); the rod is back at the step's start";
  throw NewtonFailure(message.str(), "Rod::advance");
}

void ImplicitStepper::save_state(SnapshotWriter& out) const {
  out.section("ImplicitStepper");
  out.put(has_history_);
  out.put(previous_step_);
  out.put_matrix(previous_position_increments_);
  out.put_matrix(previous_rotation_increments_);
  out.put_matrix(previous_velocities_);
  out.put_matrix(previous_angular_velocities_);
  out.put(matrix_step_);
  if (matrix_step_ != 0.0) jacobian_.save_factors(out);
}

void ImplicitStepper::load_state(SnapshotReader& in) {
  in.section("ImplicitStepper");
  const bool has_history = in.get_bool();
  const double previous_step = in.get_double();
  Vectors positions = previous_position_increments_, rotations = previous_rotation_increments_;
  Vectors velocities = previous_velocities_, angular = previous_angular_velocities_;
  in.get_matrix(positions);
  in.get_matrix(rotations);
  in.get_matrix(velocities);
  in.get_matrix(angular);
  const double matrix_step = in.get_double();
  if (matrix_step != 0.0) jacobian_.load_factors(in);
  matrix_step_ = matrix_step;
  has_history_ = has_history;
  previous_step_ = previous_step;
  previous_position_increments_ = std::move(positions);
  previous_rotation_increments_ = std::move(rotations);
  previous_velocities_ = std::move(velocities);
  previous_angular_velocities_ = std::move(angular);
}

}  // namespace tendril::physics
