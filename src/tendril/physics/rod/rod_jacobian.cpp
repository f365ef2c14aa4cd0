#include "tendril/physics/rod/rod_jacobian.hpp"

#include <algorithm>

namespace tendril::physics {

namespace {

using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// Bandwidth of the matrix: element i's torque reaches from node i − 1 (through the dilatation
// of Voronoi point i − 1) to node i + 2, i.e. 11 unknowns either side of its rows. A cancelled
// push mixes the rows of an element's two nodes, and along a run of elements pressed into a
// wall each mixes rows already mixed by the one before (apply_wall_contacts): 14 holds one
// node more, 20 two, enough that the chain's terms left out (a quarter of a quarter of the
// neighbours' stiffness and less) slow Newton's method only to a contraction of about 0.1 per
// iteration on case 3's arm sliding along the wall.
constexpr int kBand = 11;
constexpr int kBandWithContact = 20;

}  // namespace

void RodJacobian::resize(const RodModel& model, bool with_contact) {
  const int n = model.n_elements;
  const int band = with_contact ? kBandWithContact : kBand;
  matrix_.resize(6 * n + 3, band, band);
  fixed_.assign(6 * n + 3, 0);
  push_ = Eigen::Matrix<double, 9, Eigen::Dynamic>::Zero(9, n);
  penalty_first_ = push_;
  penalty_second_ = push_;
  damping_ = push_;
  touched_.assign(n, 0);
}

void RodJacobian::begin(double effective_step) {
  matrix_.set_zero();
  stiffness_weight_ = effective_step * effective_step;
  damping_weight_ = effective_step;
  std::fill(fixed_.begin(), fixed_.end(), 0);
  if (any_contact_) {
    push_.setZero();
    penalty_first_.setZero();
    penalty_second_.setZero();
    damping_.setZero();
    std::fill(touched_.begin(), touched_.end(), 0);
    any_contact_ = false;
  }
}

void RodJacobian::save_factors(SnapshotWriter& out) const {
  matrix_.save_factors(out);
  for (char fixed : fixed_) out.put(fixed != 0);
}

void RodJacobian::load_factors(SnapshotReader& in) {
  BandMatrix matrix = matrix_;
  matrix.load_factors(in);
  std::vector<char> fixed(fixed_.size());
  for (char& value : fixed) value = in.get_bool() ? 1 : 0;
  matrix_ = std::move(matrix);
  fixed_ = std::move(fixed);
}

void RodJacobian::add_damping_diagonal(int unknown, const Eigen::Vector3d& coefficients) {
  for (int c = 0; c < 3; ++c)
    matrix_(unknown + c, unknown + c) += damping_weight_ * coefficients[c];
}

void RodJacobian::add_wall_contact(int element, const Eigen::Vector3d& normal,
                                   const Eigen::Matrix3d& d_response_d_first,
                                   const Eigen::Matrix3d& d_response_d_second, double damping,
                                   bool cancels_push) {
  const RowMajor3 projector = normal * normal.transpose();
  Eigen::Map<RowMajor3>(push_.col(element).data()) += (cancels_push ? 0.5 : 0.0) * projector;
  Eigen::Map<RowMajor3>(penalty_first_.col(element).data()) += d_response_d_first;
  Eigen::Map<RowMajor3>(penalty_second_.col(element).data()) += d_response_d_second;
  Eigen::Map<RowMajor3>(damping_.col(element).data()) += 0.25 * damping * projector;
  touched_[element] = 1;
  any_contact_ = true;
}

void RodJacobian::finish(const RodModel& model) {
  if (any_contact_) apply_wall_contacts(model);
  // Fixed rates: their rows and columns become those of the identity (their residuals are
  // zeroed by the stepper), so the other unknowns see them as constants.
  const int size = matrix_.size();
  for (int u = 0; u < size; ++u) {
    if (!fixed_[u]) continue;
    double* entries = matrix_.row(u);
    for (int c = matrix_.first_column(u); c < matrix_.end_column(u); ++c) entries[c] = 0.0;
    const int last = std::min(u + matrix_.lower(), size - 1);
    for (int r = std::max(u - matrix_.upper(), 0); r <= last; ++r) matrix_.row(r)[u] = 0.0;
    entries[u] = 1.0;
  }
}

// The wall response of element i on each of its nodes a = i and b = i + 1 is
//   ½ (−min(0, F·u) + k ε − γ v̄·u) u,   F = c_a F_a + c_b F_b
// (soft_wall.hpp; c = 1 at the rod's ends, else ½), F including the responses of the elements
// before it (contact parts run element by element). A cancelled push contributes
// −½ u uᵀ ∂F/∂(state) to both nodes' rows, i.e. adds ½ u uᵀ Σ c (M − K_row) to them, read from
// the rows as they stand after the elements before i — so the matrix follows the chain of
// pushes along the rod as far as its band reaches (entries beyond it, each a product of
// several elements' shares ¼, are left out). Then the element's own response enters its two
// nodes' rows.
void RodJacobian::apply_wall_contacts(const RodModel& model) {
  const int n = model.n_elements;
  const int band = matrix_.lower();
  for (int i = 0; i < n; ++i) {
    if (!touched_[i]) continue;
    const Eigen::Map<const RowMajor3> push(push_.col(i).data());
    // Columns 6 i − band … 6 (i + 1) + 2 + band: every column the two nodes' rows can hold.
    const int start = 6 * i - band;
    if (push.squaredNorm() > 0.0) {
      window_.setZero();
      for (int node : {i, i + 1}) {
        const double share = (node == 0 || node == n) ? 1.0 : 0.5;
        for (int r = 0; r < 3; ++r) {
          const int row = 6 * node + r;
          const double* entries = matrix_.row(row);
          const int first = std::max(matrix_.first_column(row), start);
          const int end = std::min(matrix_.end_column(row), start + kWindow);
          for (int c = first; c < end; ++c) window_(r, c - start) -= share * entries[c];
          window_(r, row - start) += share * model.node_masses[node];
        }
      }
      pending_.noalias() = push * window_;
      for (int node : {i, i + 1}) {
        for (int r = 0; r < 3; ++r) {
          const int row = 6 * node + r;
          double* entries = matrix_.row(row);
          const int first = std::max(matrix_.first_column(row), start);
          const int end = std::min(matrix_.end_column(row), start + kWindow);
          for (int c = first; c < end; ++c) entries[c] += pending_(r, c - start);
        }
      }
    }
    const Eigen::Matrix3d first = Eigen::Map<const RowMajor3>(penalty_first_.col(i).data());
    const Eigen::Matrix3d second = Eigen::Map<const RowMajor3>(penalty_second_.col(i).data());
    const Eigen::Matrix3d damping = Eigen::Map<const RowMajor3>(damping_.col(i).data());
    for (int node : {i, i + 1}) {
      add_stiffness(RodJacobian::node(node), RodJacobian::node(i), first);
      add_stiffness(RodJacobian::node(node), RodJacobian::node(i + 1), second);
      add_damping(RodJacobian::node(node), RodJacobian::node(i), -damping);
      add_damping(RodJacobian::node(node), RodJacobian::node(i + 1), -damping);
    }
  }
}

}  // namespace tendril::physics
