#include "tendril/physics/rod/band_matrix.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void BandMatrix::resize(int size, int lower, int upper) {
  require(size >= 0 && lower >= 0 && upper >= 0, "size and bandwidths must be non-negative",
          "BandMatrix");
  size_ = size;
  lower_ = lower;
  upper_ = upper;
  width_ = lower + upper + 1;
  values_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size) * width_);
  lower_columns_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size) * lower);
  upper_columns_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size) * upper);
  inverse_diagonal_ = Eigen::VectorXd::Zero(size);
}

namespace {

// The factorization and the solves, for bandwidths known at compile time (kLower, kUpper > 0:
// loops of fixed length the compiler unrolls and vectorizes) or at run time (0, 0). `values`
// is row-major with `width` = lower + upper + 1 entries a row; row r starts at column
// r − lower.
template <int kLower, int kUpper>
bool factorize_band(double* values, int size, int lower_runtime, int upper_runtime) {
  const int lower = kLower > 0 ? kLower : lower_runtime;
  const int upper = kUpper > 0 ? kUpper : upper_runtime;
  const int width = lower + upper + 1;
  auto row = [&](int r) { return values + static_cast<std::ptrdiff_t>(r) * width + lower - r; };
  // Doolittle elimination, row-oriented: for every pivot k, each row below it within the band
  // loses a multiple of row k; both rows are contiguous over columns k + 1 … k + upper.
  for (int k = 0; k < size; ++k) {
    const double* pivot_row = row(k);
    const double pivot = pivot_row[k];
    if (!std::isfinite(pivot) || pivot == 0.0) return false;
    const double inverse = 1.0 / pivot;
    const int last_row = std::min(k + lower, size - 1);
    const bool full = k + upper < size;
    for (int i = k + 1; i <= last_row; ++i) {
      double* target = row(i);
      const double factor = target[k] * inverse;
      target[k] = factor;
      if (factor == 0.0) continue;
      if (kUpper > 0 && full) {
#pragma omp simd
        for (int c = 1; c <= kUpper; ++c) target[k + c] -= factor * pivot_row[k + c];
      } else {
        const int end = std::min(k + upper + 1, size);
        for (int c = k + 1; c < end; ++c) target[c] -= factor * pivot_row[c];
      }
    }
  }
  return true;
}

// Column-oriented substitution on the factors copied by columns (`lower_stride`, `upper_stride`
// entries apart, of which the first kLower, kUpper are used): once an unknown is known, it is
// taken out of the equations below (above) it. With the bandwidth fixed, the pending
// subtractions for the next rows are kept in a small array, so the chain from one unknown to the
// next is one multiply-add. Kept scalar: vectorized, the shift of that array by one entry per
// unknown becomes vector stores and loads of it offset by one entry, each load waiting for the
// stores before it (a store-forwarding stall that made the band-20 solve half of the time of
// case 3's implicit step).
template <int kLower, int kUpper>
#if defined(__GNUC__) && !defined(__clang__)
__attribute__((optimize("no-tree-vectorize", "no-tree-slp-vectorize")))
#endif
void solve_fixed(const double* lower_columns, const double* upper_columns,
                 const double* inverse_diagonal, int size, int lower_stride, int upper_stride,
                 double* b) {
  std::array<double, kLower + 1> pending{};
  for (int k = 0; k < size; ++k) {
    const double y = b[k] - pending[0];
    b[k] = y;
    const double* column = lower_columns + static_cast<std::ptrdiff_t>(k) * lower_stride;
    const int count = std::min(kLower, size - 1 - k);
    for (int j = 0; j < kLower - 1; ++j) {
      pending[j] = pending[j + 1] + (j < count ? column[j] * y : 0.0);
    }
    pending[kLower - 1] = kLower - 1 < count ? column[kLower - 1] * y : 0.0;
  }
  std::array<double, kUpper + 1> waiting{};
  for (int k = size - 1; k >= 0; --k) {
    const double x = (b[k] - waiting[0]) * inverse_diagonal[k];
    b[k] = x;
    const double* column = upper_columns + static_cast<std::ptrdiff_t>(k) * upper_stride;
    const int count = std::min(kUpper, k);
    for (int j = 0; j < kUpper - 1; ++j) {
      waiting[j] = waiting[j + 1] + (j < count ? column[j] * x : 0.0);
    }
    waiting[kUpper - 1] = kUpper - 1 < count ? column[kUpper - 1] * x : 0.0;
  }
}

void solve_any(const double* lower_columns, const double* upper_columns,
               const double* inverse_diagonal, int size, int lower, int upper, double* b) {
  for (int k = 0; k < size; ++k) {
    const double* column = lower_columns + static_cast<std::ptrdiff_t>(k) * lower;
    const int count = std::min(lower, size - 1 - k);
    for (int j = 0; j < count; ++j) b[k + 1 + j] -= column[j] * b[k];
  }
  for (int k = size - 1; k >= 0; --k) {
    b[k] *= inverse_diagonal[k];
    const double* column = upper_columns + static_cast<std::ptrdiff_t>(k) * upper;
    const int count = std::min(upper, k);
    for (int j = 0; j < count; ++j) b[k - 1 - j] -= column[j] * b[k];
  }
}

}  // namespace

// The rod's bandwidths (RodJacobian) get kernels of their own.
bool BandMatrix::factorize() {
  bool factorized;
  if (lower_ == 11 && upper_ == 11) {
    factorized = factorize_band<11, 11>(values_.data(), size_, 11, 11);
  } else if (lower_ == 20 && upper_ == 20) {
    factorized = factorize_band<20, 20>(values_.data(), size_, 20, 20);
  } else {
    factorized = factorize_band<0, 0>(values_.data(), size_, lower_, upper_);
  }
  if (!factorized) return false;
  // The factors by columns for the solves: L(k + 1 + j, k) and U(k − 1 − j, k), j = 0, 1, …
  for (int k = 0; k < size_; ++k) {
    double* lower_column = lower_columns_.data() + static_cast<Eigen::Index>(k) * lower_;
    for (int j = 0; j < lower_ && k + 1 + j < size_; ++j) lower_column[j] = row(k + 1 + j)[k];
    double* upper_column = upper_columns_.data() + static_cast<Eigen::Index>(k) * upper_;
    for (int j = 0; j < upper_ && k - 1 - j >= 0; ++j) upper_column[j] = row(k - 1 - j)[k];
    inverse_diagonal_[k] = 1.0 / row(k)[k];
  }
  find_solve_band();
  return true;
}

// Without pivoting the factors keep the zeros of the matrix outside its profile, so a matrix of
// the wide contact band whose entries all lie within 11 diagonals (no element touches a wall)
// has factors within them too and is solved by the narrow kernel: the same sums without the
// terms that are exactly zero.
void BandMatrix::find_solve_band() {
  solve_lower_ = lower_;
  solve_upper_ = upper_;
  constexpr int kNarrow = 11;
  if (lower_ <= kNarrow || upper_ <= kNarrow) return;
  for (int k = 0; k < size_; ++k) {
    const double* lower_column = lower_columns_.data() + static_cast<Eigen::Index>(k) * lower_;
    const double* upper_column = upper_columns_.data() + static_cast<Eigen::Index>(k) * upper_;
    for (int j = kNarrow; j < lower_; ++j) {
      if (lower_column[j] != 0.0) return;
    }
    for (int j = kNarrow; j < upper_; ++j) {
      if (upper_column[j] != 0.0) return;
    }
  }
  solve_lower_ = solve_upper_ = kNarrow;
}

void BandMatrix::solve(double* b) const {
  const double *lower = lower_columns_.data(), *upper = upper_columns_.data();
  const double* inverse = inverse_diagonal_.data();
  if (solve_lower_ == 11 && solve_upper_ == 11) {
    return solve_fixed<11, 11>(lower, upper, inverse, size_, lower_, upper_, b);
  }
  if (solve_lower_ == 20 && solve_upper_ == 20) {
    return solve_fixed<20, 20>(lower, upper, inverse, size_, lower_, upper_, b);
  }
  solve_any(lower, upper, inverse, size_, lower_, upper_, b);
}

void BandMatrix::save_factors(SnapshotWriter& out) const {
  out.put_matrix(lower_columns_);
  out.put_matrix(upper_columns_);
  out.put_matrix(inverse_diagonal_);
}

void BandMatrix::load_factors(SnapshotReader& in) {
  Eigen::VectorXd lower = lower_columns_, upper = upper_columns_, inverse = inverse_diagonal_;
  in.get_matrix(lower);
  in.get_matrix(upper);
  in.get_matrix(inverse);
  lower_columns_ = std::move(lower);
  upper_columns_ = std::move(upper);
  inverse_diagonal_ = std::move(inverse);
  find_solve_band();
}

Eigen::MatrixXd BandMatrix::dense() const {
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(size_, size_);
  for (int r = 0; r < size_; ++r) {
    for (int c = first_column(r); c < end_column(r); ++c) matrix(r, c) = row(r)[c];
  }
  return matrix;
}

}  // namespace tendril::physics
