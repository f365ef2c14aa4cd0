#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tendril/core/snapshot.hpp"
#include "tendril/physics/lattice/lattice_load.hpp"
#include "tendril/physics/lattice/lattice_model.hpp"

namespace tendril::physics {

class ImplicitSolver;

// How a lattice is advanced in time.
//   kBackwardEuler: M (v₊ − v) = h f(x₊, v₊), x₊ = x + h v₊ — Vega's
//     ImplicitBackwardEulerSparse scheme — solved by Newton's method on v₊ with a sparse LDLᵀ
//     factorization (Eigen) per iteration (ImplicitSolver). Unconditionally stable, so the
//     step is set by accuracy, not by the springs' frequencies; first order, and it damps a
//     mode of frequency ω at a rate ≈ ω²h/2 on top of the physical damping.
//   kBdf2: the second-order backward differentiation formula,
//     x₊ = x̂ + ĥ v₊,  M (v₊ − v̂) = ĥ f(x₊, v₊),  x̂ = (4x − x₋)/3, v̂ = (4v − v₋)/3, ĥ = 2h/3,
//     the same Newton solve from an extrapolated start (x₋, v₋: the state one step back; the
//     first step after construction or set_state is a backward-Euler step). Also L-stable, but
//     its numerical damping falls as (ωh)⁴ instead of (ωh)², so the beam's second and third
//     bending modes keep their physical damping at steps of 10 ms.
//   kSymplecticEuler: v₊ = v + h M⁻¹ f(x, v), x₊ = x + h v₊; stable only below h ≈ 2/ω_max
//     (≈ 3.5e-4 s for the seed's beam), the reference for the implicit steps.
enum class LatticeIntegrator { kBackwardEuler, kBdf2, kSymplecticEuler };

struct LatticeNumerics {
  LatticeIntegrator integrator = LatticeIntegrator::kBackwardEuler;
  double time_step = 0.01;    // s
  int newton_iterations = 1;  // implicit only
  // Raises tendril::Error naming `where` and the field.
  void validate(const std::string& where) const;
};

struct LatticeState {
  Eigen::Matrix2Xd positions;   // m, lab frame
  Eigen::Matrix2Xd velocities;  // m/s
  double time = 0.0;            // s
};

// A planar mass-spring lattice: an immutable LatticeModel, its evolving LatticeState, the
// loads attached to it and the integrator of its LatticeNumerics.
//
//   Lattice beam(build_beam_model(spec), numerics);
//   auto& couples = beam.add<RowCouples>(pairs);
//   bool finite = beam.advance(5);
//
// Fixed nodes keep their rest positions and zero velocity.
class Lattice {
 public:
  // Starts at rest in the model's rest positions. Raises tendril::Error on an invalid model
  // or numerics.
  Lattice(LatticeModel model, LatticeNumerics numerics);
  ~Lattice();
  Lattice(const Lattice&) = delete;
  Lattice& operator=(const Lattice&) = delete;
  Lattice(Lattice&&) noexcept;
  Lattice& operator=(Lattice&&) noexcept;

  template <typename Load, typename... Args>
  Load& add(Args&&... args) {
    static_assert(std::is_base_of_v<LatticeLoad, Load>);
    auto load = std::make_unique<Load>(std::forward<Args>(args)...);
    Load& reference = *load;
    attach(std::move(load));
    return reference;
  }
  void attach(std::unique_ptr<LatticeLoad> load);

  // Advances `steps` time steps. Returns false if the state became non-finite (NaN, ∞, or an
  // implicit system that could not be factorized — a blow-up); the lattice then stops
  // advancing and keeps returning false until its state is set anew (set_state).
  [[nodiscard]] bool advance(int steps = 1);
  bool state_is_finite() const;

  const LatticeModel& model() const { return model_; }
  const LatticeNumerics& numerics() const { return numerics_; }
  const LatticeState& state() const { return state_; }
  // Plants a state (tests, resets); fixed nodes are put back at rest. Re-arms a lattice that
  // reported a blow-up when the new state is finite.
  void set_state(const LatticeState& state);
  double time() const { return state_.time; }

  // Internal forces plus the loads at the current state, N (fixed nodes: the reactions).
  Eigen::Matrix2Xd total_forces() const;
  double kinetic_energy() const;
  double elastic_energy() const;

  // Positions, velocities, time, BDF2's previous step, the finite flag and every load's own
  // state, in attachment order; advancing after load_state repeats advancing after save_state bit
  // for bit. load_state raises Error on a snapshot of another lattice size or other loads and then
  // leaves the lattice as it was.
  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  void step_symplectic(double h);
  bool step_implicit(double h);
  void evaluate_loads(const Eigen::Matrix2Xd& positions);  // into external_forces_

  LatticeModel model_;
  LatticeNumerics numerics_;
  LatticeState state_;
  // BDF2's state one step back; false after construction, set_state or a backward-Euler run.
  Eigen::Matrix2Xd previous_positions_, previous_velocities_;
  bool has_previous_ = false;
  std::vector<std::unique_ptr<LatticeLoad>> loads_;
  std::unique_ptr<ImplicitSolver> implicit_;
  Eigen::Matrix2Xd external_forces_, forces_, start_positions_, start_velocities_;  // workspace
  bool finite_ = true;
};

}  // namespace tendril::physics
