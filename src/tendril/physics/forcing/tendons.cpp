#include "tendril/physics/forcing/tendons.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

// Row `row` of element i's directors (d1, d2 or d3 in the lab frame).
Eigen::Vector3d director_row(const RodState& state, int row, int i) {
  return Eigen::Vector3d(state.directors(3 * row, i), state.directors(3 * row + 1, i),
                         state.directors(3 * row + 2, i));
}

// Q_iᵀ r for an offset r = (r1, r2, 0).
Eigen::Vector3d lab_offset(const RodState& state, int i, const Eigen::Vector3d& offset) {
  return offset.x() * director_row(state, 0, i) + offset.y() * director_row(state, 1, i);
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
  const Eigen::Vector3d& r = offsets_[tendon];
  double length = state.lengths.sum();
  const Eigen::Index joints = state.curvatures.cols();
  for (Eigen::Index j = 0; j < joints; ++j) {
    // D̂_j (r × κ_j)·d3 (κ per rest length) is the joint's shortening on the side of r.
    length -= joint_lengths_[j] * (r.x() * state.curvatures(1, j) - r.y() * state.curvatures(0, j));
  }
  return length;
}

void Tendons::add_loads(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  for (int k = 0; k < count(); ++k) {
    const double length = path_length(state, k);
    const double tension =
        std::max(0.0, tensions_at_rest_[k] + stiffnesses_[k] * (length - rest_path_lengths_[k]));
    path_lengths_[k] = length;
    tensions_[k] = tension;
    if (tension == 0.0) continue;
    // Compression T along each element.
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d push = tension * state.tangents.col(i);
      state.external_forces.col(i) += push;
      state.external_forces.col(i + 1) -= push;
    }
    // The couple T t̄ × r̄ across each joint, +C on the distal element, −C on the proximal one:
    // it turns the distal element towards the tendon's side.
    const Eigen::Vector3d& r = offsets_[k];
    const double radius = r.norm();
    for (int j = 0; j + 1 < n; ++j) {
      Eigen::Vector3d offset = lab_offset(state, j, r) + lab_offset(state, j + 1, r);
      offset *= radius / offset.norm();
      const Eigen::Vector3d tangent =
          (director_row(state, 2, j) + director_row(state, 2, j + 1)).normalized();
      const Eigen::Vector3d couple = tension * tangent.cross(offset);
      state.external_torques.col(j + 1) += state.director(j + 1) * couple;
      state.external_torques.col(j) -= state.director(j) * couple;
    }
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
