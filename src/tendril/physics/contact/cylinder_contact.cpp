#include "tendril/physics/contact/cylinder_contact.hpp"

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
    bounds_.push_back({cylinder.start + 0.5 * cylinder.length * cylinder.axis,
                       0.5 * cylinder.length + cylinder.radius});
  }
}

void CylinderContact::add_contact_loads(const RodModel& model, RodState& state) {
  contacts_ = 0;
  for (std::size_t c = 0; c < cylinders_.size(); ++c) {
    const Cylinder& cylinder = cylinders_[c];
    const Bounds& bounds = bounds_[c];
    const Eigen::Vector3d axis_end = cylinder.end();
    for (int i = 0; i < model.n_elements; ++i) {
      // Cheap rejection: the element's bounding sphere misses the cylinder's.
      const Eigen::Vector3d middle = 0.5 * (state.positions.col(i) + state.positions.col(i + 1));
      const double reach = bounds.reach + 0.5 * state.lengths[i] + state.radii[i];
      if ((middle - bounds.centre).squaredNorm() > reach * reach) continue;

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
