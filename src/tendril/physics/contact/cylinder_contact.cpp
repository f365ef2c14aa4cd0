#include "tendril/physics/contact/cylinder_contact.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/contact/segment_distance.hpp"

namespace tendril::physics {

CylinderContact::CylinderContact(std::vector<Cylinder> cylinders, SoftWall wall)
    : cylinders_(std::move(cylinders)), wall_(wall) {
  wall_.validate("CylinderContact");
  for (std::size_t c = 0; c < cylinders_.size(); ++c) {
    const Cylinder& cylinder = cylinders_[c];
    const std::string where = "CylinderContact: cylinder " + std::to_string(c);
    require(cylinder.start.allFinite(), "start must be finite", where);
    require(cylinder.axis.allFinite() && std::abs(cylinder.axis.norm() - 1.0) < 1e-9,
            "axis must be a unit vector", where);
    require(std::isfinite(cylinder.length) && cylinder.length >= 0.0,
            "length must be finite and non-negative", where);
    require(std::isfinite(cylinder.radius) && cylinder.radius > 0.0,
            "radius must be finite and positive", where);
  }
}

void CylinderContact::attach(const RodModel& model, const RodState&) {
  midpoints_ = Vectors::Zero(3, model.n_elements);
  element_reach_ = Eigen::VectorXd::Zero(model.n_elements);
  near_ = Eigen::VectorXd::Zero(model.n_elements);
}

void CylinderContact::add_contact_loads(const RodModel& model, RodState& state) {
  contacts_ = 0;
  const int n = model.n_elements;
  for (int k = 0; k < 3; ++k) {
    midpoints_.row(k) = 0.5 * (state.positions.row(k).head(n) + state.positions.row(k).tail(n));
  }
  element_reach_ = 0.5 * state.lengths + state.radii;
  const double* mx = midpoints_.row(0).data();
  const double* my = midpoints_.row(1).data();
  const double* mz = midpoints_.row(2).data();
  const double* reach = element_reach_.data();
  double* near = near_.data();
  for (const Cylinder& cylinder : cylinders_) {
    // Broad phase, vectorized: an element can touch the cylinder only if its midpoint lies
    // within (its half length + its radius + the cylinder's radius) of the axis segment.
    const Eigen::Vector3d a = cylinder.start, u = cylinder.axis;
    const double length = cylinder.length, radius = cylinder.radius;
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      const double dx = mx[i] - a.x(), dy = my[i] - a.y(), dz = mz[i] - a.z();
      const double t = std::clamp(dx * u.x() + dy * u.y() + dz * u.z(), 0.0, length);
      const double px = dx - t * u.x(), py = dy - t * u.y(), pz = dz - t * u.z();
      const double limit = reach[i] + radius;
      near[i] = px * px + py * py + pz * pz <= limit * limit ? 1.0 : 0.0;
    }
    const Eigen::Vector3d axis_end = cylinder.end();
    for (int i = 0; i < n; ++i) {
      if (near[i] == 0.0) continue;
      const ClosestPoints closest = closest_points_between_segments(
          state.positions.col(i), state.positions.col(i + 1), cylinder.start, axis_end);
      const Eigen::Vector3d gap = closest.on_first - closest.on_second;
      const double distance = gap.norm();
      const double penetration = state.radii[i] + cylinder.radius - distance;
      if (penetration < 0.0 || distance <= 0.0) continue;
      ++contacts_;
      add_wall_response(wall_, model, state, i, gap / distance, penetration);
    }
  }
}

PlaneContact::PlaneContact(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                           SoftWall wall)
    : point_(point), normal_(normal), wall_(wall) {
  wall_.validate("PlaneContact");
  require(point.allFinite(), "point must be finite", "PlaneContact");
  require(normal.allFinite() && std::abs(normal.norm() - 1.0) < 1e-9, "normal must be a unit vector",
          "PlaneContact");
}

void PlaneContact::add_contact_loads(const RodModel& model, RodState& state) {
  for (int i = 0; i < model.n_elements; ++i) {
    const Eigen::Vector3d middle = 0.5 * (state.positions.col(i) + state.positions.col(i + 1));
    const double penetration = state.radii[i] - (middle - point_).dot(normal_);
    if (penetration < 0.0) continue;
    add_wall_response(wall_, model, state, i, normal_, penetration);
  }
}

}  // namespace tendril::physics
