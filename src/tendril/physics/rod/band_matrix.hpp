#pragma once

#include <Eigen/Core>

#include "tendril/core/snapshot.hpp"

namespace tendril::physics {

// A square matrix whose entries vanish beyond `lower` diagonals below and `upper` diagonals
// above the main one, stored row by row: row i holds columns i − lower … i + upper. Factorized
// in place as L U without pivoting — no fill-in outside the band, so factorization and solves
// cost O(size · lower · upper) and O(size · (lower + upper)) and never allocate. Without
// pivoting the factorization suits matrices dominated by a positive diagonal or symmetric
// positive definite ones (as the Newton matrix of an implicit rod step, M + h² K, is near
// equilibrium); a pivot that is zero or not finite fails the factorization.
class BandMatrix {
 public:
  void resize(int size, int lower, int upper);
  void set_zero() { values_.setZero(); }

  int size() const { return size_; }
  int lower() const { return lower_; }
  int upper() const { return upper_; }
  // The bandwidths the last factors fill and the solves use: lower() and upper(), or 11 when a
  // wider matrix has no entry beyond 11 diagonals.
  int solve_lower() const { return solve_lower_; }
  int solve_upper() const { return solve_upper_; }

  // Entry (row, col); |col − row| must lie within the band.
  double& operator()(int row, int col) { return values_[index(row, col)]; }
  double operator()(int row, int col) const { return values_[index(row, col)]; }
  // Row `row` addressed by column: row(r)[c] is entry (r, c) for c in the band of row r.
  double* row(int r) { return values_.data() + static_cast<Eigen::Index>(r) * width_ + lower_ - r; }
  const double* row(int r) const {
    return values_.data() + static_cast<Eigen::Index>(r) * width_ + lower_ - r;
  }
  // The first and one past the last column of row r's band inside the matrix.
  int first_column(int r) const { return r > lower_ ? r - lower_ : 0; }
  int end_column(int r) const { return r + upper_ + 1 < size_ ? r + upper_ + 1 : size_; }

  // Replaces the matrix by its factors L (unit lower, below the diagonal) and U. Returns false,
  // leaving the values undefined, at a pivot that is zero or not finite.
  [[nodiscard]] bool factorize();
  // Solves (L U) x = b in place (b ← x), after factorize(), which also keeps the factors by
  // columns for it, within the bandwidths the factors fill (solve_lower(), solve_upper()).
  void solve(double* b) const;

  // The factors (what solve uses) in and out of snapshots; load_factors reads everything before
  // it changes anything.
  void save_factors(SnapshotWriter& out) const;
  void load_factors(SnapshotReader& in);

  // The matrix as a dense one (tests).
  Eigen::MatrixXd dense() const;

 private:
  void find_solve_band();
  Eigen::Index index(int row, int col) const {
    return static_cast<Eigen::Index>(row) * width_ + lower_ + col - row;
  }

  int size_ = 0, lower_ = 0, upper_ = 0, width_ = 1;
  int solve_lower_ = 0, solve_upper_ = 0;
  Eigen::VectorXd values_;
  // The factors again, by columns (solve), and 1/U(k, k).
  Eigen::VectorXd lower_columns_, upper_columns_, inverse_diagonal_;
};

}  // namespace tendril::physics
