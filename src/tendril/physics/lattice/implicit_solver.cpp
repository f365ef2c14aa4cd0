#include "tendril/physics/lattice/implicit_solver.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

// The index into matrix.valuePtr() of entry (row, col), which must be structurally present.
int value_slot(const Eigen::SparseMatrix<double>& matrix, int row, int col) {
  const int begin = matrix.outerIndexPtr()[col];
  const int end = matrix.outerIndexPtr()[col + 1];
  const int* rows = matrix.innerIndexPtr();
  const int* found = std::lower_bound(rows + begin, rows + end, row);
  require(found != rows + end && *found == row, "missing structural entry", "ImplicitSolver");
  return static_cast<int>(found - rows);
}

std::array<int, 3> diagonal_block(const Eigen::SparseMatrix<double>& matrix, int u) {
  if (u < 0) return {-1, -1, -1};
  return {value_slot(matrix, u, u), value_slot(matrix, u, u + 1), value_slot(matrix, u + 1, u + 1)};
}

std::array<int, 4> off_diagonal_block(const Eigen::SparseMatrix<double>& matrix, int row_u,
                                      int col_u) {
  if (row_u < 0 || col_u < 0) return {-1, -1, -1, -1};
  return {value_slot(matrix, row_u, col_u), value_slot(matrix, row_u + 1, col_u),
          value_slot(matrix, row_u, col_u + 1), value_slot(matrix, row_u + 1, col_u + 1)};
}

}  // namespace

ImplicitSolver::ImplicitSolver(const LatticeModel& model) {
  const int n = model.n_nodes();
  unknown_of_node_.assign(n, -1);
  int unknowns = 0;
  for (int i = 0; i < n; ++i) {
    if (!model.fixed[i]) {
      unknown_of_node_[i] = unknowns;
      unknowns += 2;
    }
  }
  std::vector<Eigen::Triplet<double>> pattern;
  for (int u = 0; u < unknowns; u += 2) {
    pattern.emplace_back(u, u, 0.0);
    pattern.emplace_back(u, u + 1, 0.0);
    pattern.emplace_back(u + 1, u + 1, 0.0);
  }
  for (const Spring& spring : model.springs) {
    const int a = unknown_of_node_[spring.a], b = unknown_of_node_[spring.b];
    if (a < 0 || b < 0) continue;
    const int low = std::min(a, b), high = std::max(a, b);
    for (int c = 0; c < 2; ++c) {
      for (int r = 0; r < 2; ++r) pattern.emplace_back(low + r, high + c, 0.0);
    }
  }
  matrix_.resize(unknowns, unknowns);
  matrix_.setFromTriplets(pattern.begin(), pattern.end());
  matrix_.makeCompressed();

  diagonal_slots_.resize(unknowns);
  for (int u = 0; u < unknowns; ++u) diagonal_slots_[u] = value_slot(matrix_, u, u);
  spring_slots_.reserve(model.springs.size());
  for (const Spring& spring : model.springs) {
    const int a = unknown_of_node_[spring.a], b = unknown_of_node_[spring.b];
    SpringSlots slots{diagonal_block(matrix_, a), diagonal_block(matrix_, b), {-1, -1, -1, -1}};
    if (a >= 0 && b >= 0)
      slots.between = off_diagonal_block(matrix_, std::min(a, b), std::max(a, b));
    spring_slots_.push_back(slots);
  }
  if (unknowns > 0) solver_.analyzePattern(matrix_);
  rhs_.resize(unknowns);
  delta_.resize(unknowns);
  velocity_.resize(2, n);
  position_.resize(2, n);
  forces_.resize(2, n);
}

void ImplicitSolver::assemble(const LatticeModel& model, const Eigen::Matrix2Xd& x,
                              const Eigen::Matrix2Xd& v, double h) {
  double* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  forces_.setZero();
  for (int i = 0; i < model.n_nodes(); ++i) {
    const int u = unknown_of_node_[i];
    if (u < 0) continue;
    const double mass = model.masses[i] * (1.0 + h * model.mass_damping);
    values[diagonal_slots_[u]] += mass;
    values[diagonal_slots_[u + 1]] += mass;
    forces_.col(i) -= model.mass_damping * model.masses[i] * v.col(i);
  }
  const double h2 = h * h;
  for (std::size_t s = 0; s < model.springs.size(); ++s) {
    const Spring& spring = model.springs[s];
    const Eigen::Vector2d d = x.col(spring.b) - x.col(spring.a);
    const double length = d.norm();
    const Eigen::Vector2d axis = d / length;
    const double stretch_rate = (v.col(spring.b) - v.col(spring.a)).dot(axis);
    const Eigen::Vector2d f =
        (spring.stiffness * (length - spring.rest_length) + spring.damping * stretch_rate) * axis;
    forces_.col(spring.a) += f;
    forces_.col(spring.b) -= f;

    // block = (h² k + h c) ẑẑᵀ + h² k max(0, 1 − L0/l) (I − ẑẑᵀ)
    const double along = h2 * spring.stiffness + h * spring.damping;
    const double across = h2 * spring.stiffness * std::max(0.0, 1.0 - spring.rest_length / length);
    const double xx = across + (along - across) * axis.x() * axis.x();
    const double xy = (along - across) * axis.x() * axis.y();
    const double yy = across + (along - across) * axis.y() * axis.y();
    const SpringSlots& slots = spring_slots_[s];
    for (const auto& diagonal : {slots.first, slots.second}) {
      if (diagonal[0] < 0) continue;
      values[diagonal[0]] += xx;
      values[diagonal[1]] += xy;
      values[diagonal[2]] += yy;
    }
    if (slots.between[0] >= 0) {
      values[slots.between[0]] -= xx;
      values[slots.between[1]] -= xy;
      values[slots.between[2]] -= xy;
      values[slots.between[3]] -= yy;
    }
  }
}

bool ImplicitSolver::solve(const LatticeModel& model, const Eigen::Matrix2Xd& external_forces,
                           double h, int iterations, const Eigen::Matrix2Xd& x,
                           const Eigen::Matrix2Xd& v, Eigen::Matrix2Xd& positions,
                           Eigen::Matrix2Xd& velocities) {
  const int n = model.n_nodes();
  for (int i = 0; i < n; ++i) {
    const bool free = unknown_of_node_[i] >= 0;
    velocity_.col(i) = free ? Eigen::Vector2d(v.col(i)) : Eigen::Vector2d::Zero();
    position_.col(i) = x.col(i) + h * velocity_.col(i);
  }
  for (int iteration = 0; iteration < iterations; ++iteration) {
    assemble(model, position_, velocity_, h);
    for (int i = 0; i < n; ++i) {
      const int u = unknown_of_node_[i];
      if (u < 0) continue;
      // −g(v₊) = h (f + f_ext) − M (v₊ − v)
      rhs_.segment<2>(u) = h * (forces_.col(i) + external_forces.col(i)) -
                           model.masses[i] * (velocity_.col(i) - v.col(i));
    }
    solver_.factorize(matrix_);
    if (solver_.info() != Eigen::Success) return false;
    delta_ = solver_.solve(rhs_);
    for (int i = 0; i < n; ++i) {
      const int u = unknown_of_node_[i];
      if (u < 0) continue;
      velocity_.col(i) += delta_.segment<2>(u);
      position_.col(i) = x.col(i) + h * velocity_.col(i);
    }
  }
  velocities = velocity_;
  positions = position_;
  return true;
}

}  // namespace tendril::physics
