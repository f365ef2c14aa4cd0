#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/rod/band_matrix.hpp"
#include "tendril/physics/rod/rod_model.hpp"

namespace tendril::physics {

// The Newton matrix of one implicit rod step (ImplicitStepper), assembled from the derivatives
// of the loads on the rod, which the internal-load kernel and the parts add here.
//
// The unknowns are the rates at the end of the step: per node its velocity (lab frame), per
// element its angular velocity (material frame), interleaved so that the matrix is banded —
// node j's three components start at node(j) = 6 j, element i's at element(i) = 6 i + 3. A step
// of effective length γh (γ = 1 for backward Euler, 2/3 for BDF2 at a constant step) moves a
// node by γh δv and turns an element by γh δω, so with L the loads (forces on nodes, lab frame;
// torques on elements, material frame) the matrix is
//   K = diag(m, J/e) − (γh)² ∂L/∂(x, θ) − γh ∂L/∂(v, ω),
// where an element's rotation δθ (material frame) turns its directors as Q → exp(−[δθ]×) Q.
// Loads that do not depend on the state (gravity, prescribed forces and couples) add nothing.
class RodJacobian {
 public:
  static int node(int j) { return 6 * j; }
  static int element(int i) { return 6 * i + 3; }

  // ∂(load at `load`)/∂(displacement or rotation at `dof`), a 3 × 3 block.
  void add_stiffness(int load, int dof, const Eigen::Matrix3d& block) {
    add_block(load, dof, -stiffness_weight_, block);
  }
  // ∂(load at `load`)/∂(velocity or angular velocity at `rate`), a 3 × 3 block.
  void add_damping(int load, int rate, const Eigen::Matrix3d& block) {
    add_block(load, rate, -damping_weight_, block);
  }
  // A linear damping load −c ∘ (rate) on the three components starting at `unknown`.
  void add_damping_diagonal(int unknown, const Eigen::Vector3d& coefficients);

  // Soft-wall contact of element i (SoftWall, WallContacts): the wall's outward unit `normal`
  // (lab); the derivatives of the response on each of the element's nodes (it acts half on
  // each) with respect to nodes i and i + 1 with the element's force held fixed; its damping
  // γ (N·s/m) of the nodes' mean velocity along the normal; and whether the response cancelled
  // the element's push into the wall — which removes the normal component of the derivatives
  // of the element's force, taken from the matrix as it stood before any contact (see
  // apply_wall_contacts).
  void add_wall_contact(int element, const Eigen::Vector3d& normal,
                        const Eigen::Matrix3d& d_response_d_first,
                        const Eigen::Matrix3d& d_response_d_second, double damping,
                        bool cancels_push);

  // Holds the rate component `unknown` at zero (a clamped end).
  void fix_rate(int unknown) { fixed_[unknown] = 1; }

  // --- used by the stepper ---
  // Sizes the matrix for `model`; with contact, the band is wider (apply_wall_contacts).
  void resize(const RodModel& model, bool with_contact);
  // Clears the matrix and sets the step's weights γh.
  void begin(double effective_step);
  void add_diagonal(int unknown, double value) { matrix_(unknown, unknown) += value; }
  // Applies the wall contacts and the fixed rates; the matrix is then ready to factorize.
  void finish(const RodModel& model);
  bool is_fixed(int unknown) const { return fixed_[unknown] != 0; }
  // The factorized matrix and the fixed rates, for snapshots of a stepper that reuses them.
  void save_factors(SnapshotWriter& out) const;
  void load_factors(SnapshotReader& in);
  int unknowns() const { return matrix_.size(); }
  BandMatrix& matrix() { return matrix_; }
  const BandMatrix& matrix() const { return matrix_; }

 private:
  void add_block(int row, int col, double weight, const Eigen::Matrix3d& block) {
    for (int r = 0; r < 3; ++r) {
      double* entries = matrix_.row(row + r) + col;
      for (int c = 0; c < 3; ++c) entries[c] += weight * block(r, c);
    }
  }
  void apply_wall_contacts(const RodModel& model);

  BandMatrix matrix_;
  double stiffness_weight_ = 0.0, damping_weight_ = 0.0;
  std::vector<char> fixed_;
  // Per element, wall contacts summed over walls: ½ Σ u uᵀ over cancelled pushes, the
  // responses' derivatives with respect to nodes i and i + 1, and the damping's ¼ Σ γ u uᵀ
  // (3 × 3, row-major).
  Eigen::Matrix<double, 9, Eigen::Dynamic> push_, penalty_first_, penalty_second_, damping_;
  std::vector<char> touched_;
  bool any_contact_ = false;
  // Rows of an element's two nodes over every column they can hold (apply_wall_contacts).
  static constexpr int kWindow = 6 + 3 + 2 * 20;  // the contact bandwidth either side
  Eigen::Matrix<double, 3, kWindow> window_, pending_;
};

}  // namespace tendril::physics
