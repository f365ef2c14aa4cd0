#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "tendril/physics/lattice/lattice_model.hpp"

namespace tendril::physics {

// The nonlinear system of one implicit step of a mass-spring lattice (backward Euler, and BDF2
// from an extrapolated start; see LatticeIntegrator): for the free nodes' end-of-step
// velocity v₊,
//   g(v₊) = M (v₊ − v) − h [f(x + h v₊, v₊) + f_ext] = 0,   x₊ = x + h v₊,
// solved by Newton's method with the matrix
//   J = M (1 + h α) + Σ_springs [h² K_s + h c ẑẑᵀ] on the blocks (a,a), (b,b), and minus it on
//   (a,b), (b,a),   K_s = k [ẑẑᵀ + max(0, 1 − L0/l) (I − ẑẑᵀ)].
// The first iterate starts from v₊ = v, i.e. linearizes at the predictor x + h v rather than at
// x as Baraff & Witkin (1998) do: a stiff spring that turns during the step is then not
// stretched by the linearization, and one iteration is close to the converged step (the tip of
// the seed's beam, swung 0.5 m by a step couple at h = 10 ms, ends within 5 mm of where more
// iterations put it; from x, more than 10 cm away). The transverse
// (geometric) term is clamped at zero for compressed springs (Choi & Ko 2002), which keeps J
// symmetric positive definite, and the dashpot's dependence on ẑ is left out of J: both change
// only how fast Newton converges, not the step it converges to. J's sparsity is fixed by the
// springs, so the pattern is analyzed once and only refactorized per iteration.
class ImplicitSolver {
 public:
  explicit ImplicitSolver(const LatticeModel& model);

  // Solves for v₊ with `iterations` Newton iterations from the step's start `x`, `v` (m, m/s)
  // with `external_forces` (N) held over the step, and writes x₊ and v₊ to `positions` and
  // `velocities` (fixed nodes: x and zero). Returns false, writing nothing, if J could not be
  // factorized.
  bool solve(const LatticeModel& model, const Eigen::Matrix2Xd& external_forces, double h,
             int iterations, const Eigen::Matrix2Xd& x, const Eigen::Matrix2Xd& v,
             Eigen::Matrix2Xd& positions, Eigen::Matrix2Xd& velocities);

  int unknowns() const { return static_cast<int>(rhs_.size()); }

 private:
  // Value slots in matrix_ of a spring's blocks on and above the diagonal (−1: not stored, a
  // node is fixed). Diagonal blocks hold (0,0), (0,1), (1,1); the off-diagonal block, between
  // the lower and the higher unknown, (0,0), (1,0), (0,1), (1,1).
  struct SpringSlots {
    std::array<int, 3> first{}, second{};
    std::array<int, 4> between{};
  };
  // Fills matrix_ and forces_ (internal forces) at positions x, velocities v.
  void assemble(const LatticeModel& model, const Eigen::Matrix2Xd& x, const Eigen::Matrix2Xd& v,
                double h);

  std::vector<int> unknown_of_node_;  // first of the node's two unknowns, −1 when fixed
  // Upper triangle only; natural ordering, so LDLᵀ reads it in place without the permuted copy
  // an ordering costs on every factorization. A lattice numbered row by row (BeamLattice) is
  // banded, and the natural order fills in no more than AMD's would.
  Eigen::SparseMatrix<double> matrix_;
  std::vector<SpringSlots> spring_slots_;
  std::vector<int> diagonal_slots_;  // one per unknown
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>
      solver_;
  Eigen::VectorXd rhs_, delta_;
  Eigen::Matrix2Xd velocity_, position_, forces_;
};

}  // namespace tendril::physics
