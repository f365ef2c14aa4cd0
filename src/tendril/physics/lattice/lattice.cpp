#include "tendril/physics/lattice/lattice.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/lattice/implicit_solver.hpp"
#include "tendril/physics/lattice/lattice_forces.hpp"

namespace tendril::physics {

void LatticeNumerics::validate(const std::string& where) const {
  if (!(std::isfinite(time_step) && time_step > 0.0)) {
    throw Error("time_step must be finite and positive, got " + std::to_string(time_step), where);
  }
  if (newton_iterations < 1) {
    throw Error("newton_iterations must be at least 1, got " + std::to_string(newton_iterations),
                where);
  }
}

Lattice::Lattice(LatticeModel model, LatticeNumerics numerics)
    : model_(std::move(model)), numerics_(numerics) {
  model_.validate("LatticeModel");
  numerics_.validate("LatticeNumerics");
  const int n = model_.n_nodes();
  state_.positions = model_.rest_positions;
  state_.velocities = Eigen::Matrix2Xd::Zero(2, n);
  external_forces_ = Eigen::Matrix2Xd::Zero(2, n);
  forces_ = Eigen::Matrix2Xd::Zero(2, n);
  previous_positions_ = state_.positions;
  previous_velocities_ = state_.velocities;
  start_positions_ = state_.positions;
  start_velocities_ = state_.velocities;
  if (numerics_.integrator != LatticeIntegrator::kSymplecticEuler) {
    implicit_ = std::make_unique<ImplicitSolver>(model_);
  }
}

Lattice::~Lattice() = default;
Lattice::Lattice(Lattice&&) noexcept = default;
Lattice& Lattice::operator=(Lattice&&) noexcept = default;

void Lattice::attach(std::unique_ptr<LatticeLoad> load) {
  require(load != nullptr, "cannot attach a null load", "Lattice::attach");
  load->attach(model_);
  loads_.push_back(std::move(load));
}

bool Lattice::advance(int steps) {
  if (!finite_) return false;
  const double h = numerics_.time_step;
  for (int step = 0; step < steps; ++step) {
    if (numerics_.integrator != LatticeIntegrator::kSymplecticEuler) {
      if (!step_implicit(h)) {
        finite_ = false;
        return false;
      }
    } else {
      step_symplectic(h);
    }
  }
  finite_ = state_is_finite();
  return finite_;
}

bool Lattice::state_is_finite() const {
  // A sum is non-finite iff some term is (or the terms overflow, which is a blow-up too).
  return std::isfinite(state_.positions.sum() + state_.velocities.sum());
}

void Lattice::evaluate_loads(const Eigen::Matrix2Xd& positions) {
  external_forces_.setZero();
  for (const auto& load : loads_) load->add_forces(model_, positions, external_forces_);
}

void Lattice::step_symplectic(double h) {
  evaluate_loads(state_.positions);
  forces_ = external_forces_;
  add_internal_forces(model_, state_.positions, state_.velocities, forces_);
  for (int i = 0; i < model_.n_nodes(); ++i) {
    if (model_.fixed[i]) continue;
    state_.velocities.col(i) += (h / model_.masses[i]) * forces_.col(i);
    state_.positions.col(i) += h * state_.velocities.col(i);
  }
  state_.time += h;
}

bool Lattice::step_implicit(double h) {
  double step = h;
  if (numerics_.integrator == LatticeIntegrator::kBdf2 && has_previous_) {
    start_positions_ = (4.0 * state_.positions - previous_positions_) / 3.0;
    start_velocities_ = (4.0 * state_.velocities - previous_velocities_) / 3.0;
    step = 2.0 * h / 3.0;
  } else {
    start_positions_ = state_.positions;
    start_velocities_ = state_.velocities;
  }
  // Loads at the predicted end of the step, the Newton solve's starting point (for BDF2 within
  // O(h²) of x₊, which keeps a position-dependent load from costing an order of accuracy).
  forces_ = start_positions_ + step * start_velocities_;
  for (int i = 0; i < model_.n_nodes(); ++i) {
    if (model_.fixed[i]) forces_.col(i) = model_.rest_positions.col(i);
  }
  evaluate_loads(forces_);
  previous_positions_.swap(state_.positions);
  previous_velocities_.swap(state_.velocities);
  if (!implicit_->solve(model_, external_forces_, step, numerics_.newton_iterations,
                        start_positions_, start_velocities_, state_.positions, state_.velocities)) {
    previous_positions_.swap(state_.positions);
    previous_velocities_.swap(state_.velocities);
    return false;
  }
  has_previous_ = numerics_.integrator == LatticeIntegrator::kBdf2;
  state_.time += h;
  return true;
}

void Lattice::set_state(const LatticeState& state) {
  const int n = model_.n_nodes();
  require(state.positions.cols() == n && state.velocities.cols() == n,
          "state must have one column per node (" + std::to_string(n) + ")", "Lattice::set_state");
  state_ = state;
  for (int i = 0; i < n; ++i) {
    if (!model_.fixed[i]) continue;
    state_.positions.col(i) = model_.rest_positions.col(i);
    state_.velocities.col(i).setZero();
  }
  has_previous_ = false;
  finite_ = state_is_finite();
}

Eigen::Matrix2Xd Lattice::total_forces() const {
  Eigen::Matrix2Xd forces = Eigen::Matrix2Xd::Zero(2, model_.n_nodes());
  for (const auto& load : loads_) load->add_forces(model_, state_.positions, forces);
  add_internal_forces(model_, state_.positions, state_.velocities, forces);
  return forces;
}

double Lattice::kinetic_energy() const {
  return physics::kinetic_energy(model_, state_.velocities);
}

double Lattice::elastic_energy() const { return physics::elastic_energy(model_, state_.positions); }

void Lattice::save_state(SnapshotWriter& out) const {
  out.section("Lattice");
  out.put_matrix(state_.positions);
  out.put_matrix(state_.velocities);
  out.put(state_.time);
  out.put_matrix(previous_positions_);
  out.put_matrix(previous_velocities_);
  out.put(has_previous_);
  out.put(finite_);
  out.put(static_cast<int64_t>(loads_.size()));
  for (const auto& load : loads_) load->save_state(out);
}

void Lattice::load_state(SnapshotReader& in) {
  in.section("Lattice");
  LatticeState state = state_;
  in.get_matrix(state.positions);
  in.get_matrix(state.velocities);
  state.time = in.get_double();
  Eigen::Matrix2Xd previous_positions = previous_positions_;
  Eigen::Matrix2Xd previous_velocities = previous_velocities_;
  in.get_matrix(previous_positions);
  in.get_matrix(previous_velocities);
  const bool has_previous = in.get_bool();
  const bool finite = in.get_bool();
  const int64_t loads = in.get_int64();
  if (loads != static_cast<int64_t>(loads_.size())) {
    throw Error("snapshot has " + std::to_string(loads) + " loads, this lattice " +
                    std::to_string(loads_.size()),
                "Lattice::load_state");
  }
  // Loads restore themselves all or nothing; undo the earlier ones if a later one refuses.
  Snapshot before;
  SnapshotWriter before_writer(before);
  for (const auto& load : loads_) load->save_state(before_writer);
  try {
    for (const auto& load : loads_) load->load_state(in);
  } catch (...) {
    SnapshotReader restore(before);
    for (const auto& load : loads_) load->load_state(restore);
    throw;
  }
  state_ = std::move(state);
  previous_positions_ = std::move(previous_positions);
  previous_velocities_ = std::move(previous_velocities);
  has_previous_ = has_previous;
  finite_ = finite;
}

}  // namespace tendril::physics
