#include "tendril/physics/rod/rod.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/internal_loads.hpp"
#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

Rod::Rod(const RodSpec& spec) : model_(RodModel::build(spec)), integrator_(spec.integrator) {
  state_.resize(model_);
  if (integrator_ != RodIntegrator::kPositionVerlet) {
    implicit_ = std::make_unique<ImplicitStepper>(model_, integrator_, spec.newton);
  }
  const Eigen::Vector3d d3 = spec.direction;
  const Eigen::Vector3d d1 = spec.normal;
  const Eigen::Vector3d d2 = d3.cross(d1);
  Eigen::Matrix3d frame;
  frame.row(0) = d1;
  frame.row(1) = d2;
  frame.row(2) = d3;
  double arc_length = 0.0;
  state_.positions.col(0) = spec.base_position;
  for (int i = 0; i < model_.n_elements; ++i) {
    arc_length += model_.rest_lengths[i];
    state_.positions.col(i + 1) = spec.base_position + arc_length * d3;
    state_.set_director(i, frame);
  }
  state_changed();
}

void Rod::attach(std::unique_ptr<RodPart> part) {
  require(part != nullptr, "cannot attach a null part", "Rod::attach");
  part->attach(model_, state_);
  stages_.add(part.get());
  parts_.push_back(std::move(part));
  if (implicit_) implicit_->configure(model_, stages_);
}

void Rod::state_changed() {
  compute_strains(model_, state_);
  finite_ = state_is_finite();
  if (implicit_) implicit_->reset_history();
}

void Rod::save_state(SnapshotWriter& out) const {
  out.section("Rod");
  out.put(static_cast<int64_t>(model_.n_elements));
  out.put(static_cast<int64_t>(parts_.size()));
  out.put_matrix(state_.positions);
  out.put_matrix(state_.velocities);
  out.put_matrix(state_.directors);
  out.put_matrix(state_.angular_velocities);
  out.put(state_.time);
  out.put(finite_);
  for (const auto& part : parts_) part->save_state(out);
  if (implicit_) implicit_->save_state(out);
}

void Rod::load_state(SnapshotReader& in) {
  // All or nothing: on a failure part-way, put back what was there.
  Snapshot backup;
  SnapshotWriter writer(backup);
  save_state(writer);
  try {
    load_state_unchecked(in);
  } catch (...) {
    SnapshotReader restore(backup);
    load_state_unchecked(restore);
    throw;
  }
}

void Rod::load_state_unchecked(SnapshotReader& in) {
  in.section("Rod");
  const int64_t n_elements = in.get_int64();
  const int64_t n_parts = in.get_int64();
  if (n_elements != model_.n_elements || n_parts != static_cast<int64_t>(parts_.size())) {
    throw Error("snapshot of a rod with " + std::to_string(n_elements) + " elements and " +
                    std::to_string(n_parts) + " parts; this rod has " +
                    std::to_string(model_.n_elements) + " and " + std::to_string(parts_.size()),
                "Rod::load_state");
  }
  in.get_matrix(state_.positions);
  in.get_matrix(state_.velocities);
  in.get_matrix(state_.directors);
  in.get_matrix(state_.angular_velocities);
  state_.time = in.get_double();
  const bool finite = in.get_bool();
  for (const auto& part : parts_) part->load_state(in);
  if (implicit_) implicit_->load_state(in);
  compute_strains(model_, state_);
  finite_ = finite;
}

bool Rod::state_is_finite() const {
  // A sum is non-finite iff some term is (or the terms overflow, which is a blow-up too).
  double sum = state_.positions.sum() + state_.velocities.sum() + state_.angular_velocities.sum();
  sum += state_.directors.sum();
  return std::isfinite(sum);
}

bool Rod::advance(int steps) {
  if (!finite_) return false;
  if (steps <= 0) return true;
  if (implicit_) return advance_implicitly(steps, model_.time_step);
  // Position Verlet (Gazzola et al. 2018, §3.3), per step: half kinematic step, constraints,
  // loads, dynamic step, rate constraints and damping, half kinematic step, constraints.
  // Between two steps the second half of one and the first half of the next use the same
  // rates, so they are taken as one full kinematic step.
  const double dt = model_.time_step;
  kinematic_step(0.5 * dt);
  for (int s = 0; s < steps; ++s) {
    state_.time += 0.5 * dt;
    for (RodPart* part : stages_.constrain_values) part->constrain_values(model_, state_);
    dynamic_stage();
    const bool last = s + 1 == steps;
    kinematic_step(last ? 0.5 * dt : dt);
    state_.time += 0.5 * dt;
  }
  for (RodPart* part : stages_.constrain_values) part->constrain_values(model_, state_);
  // Read-outs (strains, energies, radii) describe the configuration at the end of the call.
  compute_strains(model_, state_);
  finite_ = state_is_finite();
  return finite_;
}

bool Rod::advance_by(double duration, int steps) {
  if (!implicit_) {
    throw Error("a position-Verlet rod steps at its fixed time_step; use advance(steps)",
                "Rod::advance_by");
  }
  if (!(std::isfinite(duration) && duration > 0.0) || steps < 1) {
    throw Error("need a finite, positive duration and at least one step, got " +
                    std::to_string(duration) + " s in " + std::to_string(steps),
                "Rod::advance_by");
  }
  if (!finite_) return false;
  return advance_implicitly(steps, duration / steps);
}

bool Rod::advance_implicitly(int steps, double step) {
  // A state made non-finite from outside is reported as by position Verlet, not as a failure
  // of Newton's method.
  if (!state_is_finite()) {
    finite_ = false;
    return false;
  }
  for (int s = 0; s < steps; ++s) implicit_step(step, 0);
  compute_strains(model_, state_);
  finite_ = state_is_finite();
  return finite_;
}

void Rod::implicit_step(double step, int halvings) {
  try {
    implicit_->step(model_, state_, stages_, step);
  } catch (const NewtonFailure& failure) {
    const int most = implicit_->newton().max_halvings;
    if (halvings < most) {
      implicit_->count_halving();
      implicit_step(0.5 * step, halvings + 1);
      implicit_step(0.5 * step, halvings + 1);
      return;
    }
    throw NewtonFailure(
        failure.what_wrong() +
            (most > 0 ? " (the step halved " + std::to_string(most) + " times)" : std::string()) +
            ". Take a smaller time step, or raise newton.max_iterations",
        failure.where());
  }
}

// Loads at the mid-step configuration, then velocities and angular velocities.
void Rod::dynamic_stage() {
  for (RodPart* part : stages_.start_step) part->start_step(model_, state_, model_.time_step);
  compute_internal_loads(model_, state_);
  state_.external_forces.setZero();
  state_.external_torques.setZero();
  for (RodPart* part : stages_.loads) part->add_loads(model_, state_);
  for (RodPart* part : stages_.contact) part->add_contact_loads(model_, state_);

  dynamic_step(model_.time_step);
  for (RodPart* part : stages_.constrain_rates) part->constrain_rates(model_, state_);
  for (RodPart* part : stages_.damp_rates) part->damp_rates(model_, state_);
}

void Rod::kinematic_step(double h) {
  state_.positions.noalias() += h * state_.velocities;
  const int n = model_.n_elements;
  const double largest = state_.angular_velocities.colwise().squaredNorm().maxCoeff() * h * h;
  if (!(largest < 1e-2)) {
    // A rotation beyond 0.1 rad in one step (or a non-finite rate): the general formula.
    for (int i = 0; i < n; ++i) {
      state_.set_director(
          i, exp_rotation_minus(h * state_.angular_velocities.col(i)) * state_.director(i));
    }
    return;
  }
  // Q ← exp(−h [ω]×) Q by Rodrigues' formula with the series of sin φ/φ and (1 − cos φ)/φ²
  // (exact to double precision for φ < 0.1), vectorized across elements.
  const double* w0 = state_.angular_velocities.row(0).data();
  const double* w1 = state_.angular_velocities.row(1).data();
  const double* w2 = state_.angular_velocities.row(2).data();
  double* q = state_.directors.data();
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double x = h * w0[i], y = h * w1[i], z = h * w2[i];
    const double p2 = x * x + y * y + z * z;
    const double a = 1.0 - p2 / 6.0 * (1.0 - p2 / 20.0 * (1.0 - p2 / 42.0 * (1.0 - p2 / 72.0)));
    const double b =
        0.5 * (1.0 - p2 / 12.0 * (1.0 - p2 / 30.0 * (1.0 - p2 / 56.0 * (1.0 - p2 / 90.0))));
    // exp(−[θ]×) = I − a [θ]× + b (θθᵀ − φ² I)
    const double r00 = 1.0 + b * (x * x - p2), r11 = 1.0 + b * (y * y - p2),
                 r22 = 1.0 + b * (z * z - p2);
    const double r01 = a * z + b * x * y, r10 = -a * z + b * x * y;
    const double r02 = -a * y + b * x * z, r20 = a * y + b * x * z;
    const double r12 = a * x + b * y * z, r21 = -a * x + b * y * z;
    double old[9];
    for (int k = 0; k < 9; ++k) old[k] = q[k * n + i];
    for (int c = 0; c < 3; ++c) {
      q[(0 + c) * n + i] = r00 * old[c] + r01 * old[3 + c] + r02 * old[6 + c];
      q[(3 + c) * n + i] = r10 * old[c] + r11 * old[3 + c] + r12 * old[6 + c];
      q[(6 + c) * n + i] = r20 * old[c] + r21 * old[3 + c] + r22 * old[6 + c];
    }
  }
}

// m dv/dt = F_internal + F_external;  (J/e) dω/dt = T_internal + T_external.
void Rod::dynamic_step(double dt) {
  for (int k = 0; k < 3; ++k) {
    state_.velocities.row(k).array() +=
        dt * model_.inverse_node_masses.transpose().array() *
        (state_.internal_forces.row(k).array() + state_.external_forces.row(k).array());
    state_.angular_velocities.row(k).array() +=
        dt * state_.dilatations.transpose().array() * model_.inverse_inertia.row(k).array() *
        (state_.internal_torques.row(k).array() + state_.external_torques.row(k).array());
  }
}

Eigen::Matrix3Xd Rod::sampled_node_positions(int count) const {
  require(count >= 2, "need at least 2 sampled nodes, got " + std::to_string(count),
          "Rod::sampled_node_positions");
  Eigen::Matrix3Xd samples(3, count);
  const int n = model_.n_elements;
  for (int k = 0; k < count; ++k) {
    const int node = static_cast<int>(std::lround(static_cast<double>(k) * n / (count - 1)));
    samples.col(k) = state_.positions.col(node);
  }
  return samples;
}

Eigen::Quaterniond Rod::tip_quaternion() const {
  Eigen::Quaterniond q(Eigen::Matrix3d(tip_directors().transpose()));
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;  // one representative of ±q
  return q;
}

RodEnergies Rod::energies() const {
  RodEnergies energy;
  const RodState& s = state_;
  for (int j = 0; j < model_.n_nodes(); ++j) {
    energy.translational_kinetic += 0.5 * model_.node_masses[j] * s.velocities.col(j).squaredNorm();
  }
  for (int i = 0; i < model_.n_elements; ++i) {
    const Eigen::Vector3d omega = s.angular_velocities.col(i);
    energy.rotational_kinetic +=
        0.5 * omega.dot(model_.inertia.col(i).cwiseProduct(omega)) / s.dilatations[i];
    const Eigen::Vector3d strain = s.shear_strains.col(i) - model_.rest_shear_strains.col(i);
    energy.shear_stretch += 0.5 * model_.rest_lengths[i] *
                            strain.dot(model_.shear_stiffness.col(i).cwiseProduct(strain));
  }
  for (int j = 0; j < model_.n_voronoi(); ++j) {
    const Eigen::Vector3d strain = s.curvatures.col(j) - model_.rest_curvatures.col(j);
    energy.bend_twist += 0.5 * model_.rest_voronoi_lengths[j] *
                         strain.dot(model_.bend_stiffness.col(j).cwiseProduct(strain));
  }
  return energy;
}

}  // namespace tendril::physics
