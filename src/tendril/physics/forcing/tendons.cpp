#include "tendril/physics/forcing/tendons.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"

namespace tendril::physics {

namespace {

// Q_iᵀ r for an offset r = (r1, r2, 0): r1 d1 + r2 d2 of element i (lab frame).
Eigen::Vector3d lab_offset(const RodState& state, int i, const Eigen::Vector3d& offset) {
  const Eigen::Matrix3d q = state.director(i);
  return offset.x() * q.row(0).transpose() + offset.y() * q.row(1).transpose();
}

}  // namespace

Tendons::Tendons(std::vector<Eigen::Vector3d> offsets) : offsets_(std::move(offsets)) {
  require(!offsets_.empty(), "need at least one tendon", "Tendons");
  for (const Eigen::Vector3d& offset : offsets_) {
    require(offset.allFinite() && offset.z() == 0.0 && offset.norm() > 0.0,
            "offsets must be finite, non-zero and perpendicular to d3", "Tendons");
  }
  const std::size_t n = offsets_.size();
  tensions_at_rest_.assign(n, 0.0);
  stiffnesses_.assign(n, 0.0);
  tensions_.assign(n, 0.0);
  path_lengths_.assign(n, 0.0);
  rest_path_lengths_.assign(n, 0.0);
}

void Tendons::attach(const RodModel& model, const RodState& state) {
  require(model.n_elements >= 2, "tendons need a rod of at least 2 elements", "Tendons");
  joint_lengths_ = model.rest_voronoi_lengths;
  for (int k = 0; k < count(); ++k) {
    rest_path_lengths_[k] = path_length(state, k);
    path_lengths_[k] = rest_path_lengths_[k];
  }
}

void Tendons::set_tension_law(int tendon, double tension_at_rest_length, double stiffness) {
  if (tendon < 0 || tendon >= count()) {
    throw Error("no tendon " + std::to_string(tendon) + " (have " + std::to_string(count()) + ")",
                "Tendons");
  }
  if (!std::isfinite(tension_at_rest_length) || !std::isfinite(stiffness) || stiffness < 0.0) {
    throw Error("tension law of tendon " + std::to_string(tendon) +
                    " must be finite with a non-negative stiffness",
                "Tendons");
  }
  tensions_at_rest_[tendon] = tension_at_rest_length;
  stiffnesses_[tendon] = stiffness;
}

double Tendons::path_length(const RodState& state, int tendon) const {
  // l = Σ l_i − (r × Σ_j D̂_j κ_j)·d3: the rod's length less the bending towards the tendon.
  Eigen::Vector2d bend = Eigen::Vector2d::Zero();
  for (Eigen::Index j = 0; j < state.curvatures.cols(); ++j) {
    bend += joint_lengths_[j] * Eigen::Vector2d(state.curvatures(0, j), state.curvatures(1, j));
  }
  const Eigen::Vector3d& r = offsets_[tendon];
  return state.lengths.sum() - (r.x() * bend.y() - r.y() * bend.x());
}

void Tendons::add_loads(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  // Σ_j D̂_j κ_j (material d1, d2 components) and the rod's length give every tendon's length.
  double bend1 = 0.0, bend2 = 0.0;
  const double* kappa1 = state.curvatures.row(0).data();
  const double* kappa2 = state.curvatures.row(1).data();
  const double* joint = joint_lengths_.data();
  for (int j = 0; j + 1 < n; ++j) {
    bend1 += joint[j] * kappa1[j];
    bend2 += joint[j] * kappa2[j];
  }
  const double rod_length = state.lengths.sum();
  // All tendons act through two resultants: the total compression Σ T_k and the couple arm
  // Σ T_k r_k (material d1, d2 components; N·m).
  double compression = 0.0, arm1 = 0.0, arm2 = 0.0;
  for (int k = 0; k < count(); ++k) {
    const Eigen::Vector3d& r = offsets_[k];
    const double length = rod_length - (r.x() * bend2 - r.y() * bend1);
    const double tension =
        std::max(0.0, tensions_at_rest_[k] + stiffnesses_[k] * (length - rest_path_lengths_[k]));
    path_lengths_[k] = length;
    tensions_[k] = tension;
    compression += tension;
    arm1 += tension * r.x();
    arm2 += tension * r.y();
  }
  if (compression == 0.0) return;

  // Compression Σ T along each element: +T t_i on node i, −T t_i on node i + 1.
  for (int c = 0; c < 3; ++c) {
    const double* t = state.tangents.row(c).data();
    double* f = state.external_forces.row(c).data();
    f[0] += compression * t[0];
    for (int i = 1; i < n; ++i) f[i] += compression * (t[i] - t[i - 1]);
    f[n] -= compression * t[n - 1];
  }
  if (arm1 == 0.0 && arm2 == 0.0) return;
  // Across joint j: C = t̄ × (a1 ē1 + a2 ē2), with ē1, ē2, t̄ the unit means of the two elements'
  // d1, d2, d3 (lab); +C (in element j + 1's frame) on j + 1, −C on j.
  const double* q[9];
  for (int row = 0; row < 9; ++row) q[row] = state.directors.row(row).data();
  double* torque[3];
  for (int c = 0; c < 3; ++c) torque[c] = state.external_torques.row(c).data();
  for (int j = 0; j + 1 < n; ++j) {
    Eigen::Vector3d e1(q[0][j] + q[0][j + 1], q[1][j] + q[1][j + 1], q[2][j] + q[2][j + 1]);
    Eigen::Vector3d e2(q[3][j] + q[3][j + 1], q[4][j] + q[4][j + 1], q[5][j] + q[5][j + 1]);
    Eigen::Vector3d t(q[6][j] + q[6][j + 1], q[7][j] + q[7][j + 1], q[8][j] + q[8][j + 1]);
    const Eigen::Vector3d arm = arm1 / e1.norm() * e1 + arm2 / e2.norm() * e2;
    const Eigen::Vector3d couple = t.cross(arm) / t.norm();
    for (int side = 0; side < 2; ++side) {
      const int i = j + side;
      const double sign = side == 0 ? -1.0 : 1.0;
      for (int row = 0; row < 3; ++row) {
        torque[row][i] += sign * (q[3 * row][i] * couple.x() + q[3 * row + 1][i] * couple.y() +
                                  q[3 * row + 2][i] * couple.z());
      }
    }
  }
}

void Tendons::add_load_derivatives(const RodModel& model, const RodState& state,
                                   RodJacobian& jacobian) const {
  double compression = 0.0;
  for (double tension : tensions_) compression += tension;
  if (compression == 0.0) return;
  // +C t_i on node i and −C t_i on node i + 1, with ∂t_i/∂(x_{i+1} − x_i) = (I − t tᵀ)/l.
  for (int i = 0; i < model.n_elements; ++i) {
    const Eigen::Vector3d t = state.tangents.col(i);
    const Eigen::Matrix3d block =
        compression / state.lengths[i] * (Eigen::Matrix3d::Identity() - t * t.transpose());
    const int a = RodJacobian::node(i), b = RodJacobian::node(i + 1);
    jacobian.add_stiffness(a, a, -block);
    jacobian.add_stiffness(a, b, block);
    jacobian.add_stiffness(b, a, block);
    jacobian.add_stiffness(b, b, -block);
  }
}

Eigen::Matrix3Xd Tendons::path(const RodState& state, int tendon) const {
  const Eigen::Index n = state.lengths.size();
  const Eigen::Vector3d& r = offsets_[tendon];
  Eigen::Matrix3Xd points(3, n + 1);
  points.col(0) = state.positions.col(0) + lab_offset(state, 0, r);
  for (Eigen::Index j = 1; j < n; ++j) {
    Eigen::Vector3d offset =
        lab_offset(state, static_cast<int>(j - 1), r) + lab_offset(state, static_cast<int>(j), r);
    points.col(j) = state.positions.col(j) + offset * (r.norm() / offset.norm());
  }
  points.col(n) = state.positions.col(n) + lab_offset(state, static_cast<int>(n - 1), r);
  return points;
}

void Tendons::save_state(SnapshotWriter& out) const {
  out.section("Tendons");
  out.put(std::span<const double>(tensions_at_rest_));
  out.put(std::span<const double>(stiffnesses_));
  out.put(std::span<const double>(tensions_));
  out.put(std::span<const double>(path_lengths_));
}

void Tendons::load_state(SnapshotReader& in) {
  in.section("Tendons");
  std::vector<double> at_rest = tensions_at_rest_, stiffnesses = stiffnesses_, tensions = tensions_,
                      lengths = path_lengths_;
  in.get(at_rest);
  in.get(stiffnesses);
  in.get(tensions);
  in.get(lengths);
  tensions_at_rest_ = std::move(at_rest);
  stiffnesses_ = std::move(stiffnesses);
  tensions_ = std::move(tensions);
  path_lengths_ = std::move(lengths);
}

}  // namespace tendril::physics
