#include "tendril/physics/contact/cylinder_contact.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/contact/segment_distance.hpp"

namespace tendril::physics {

namespace {

// How the normal u = w/|w|, w = p − q from the axis point q to the element's point p, turns
// with the element's nodes, p = x_i + s e and q = c + t a, both closest points: the
// conditions w·e = 0 (s free) and w·a = 0 (t free) fix δs and δt; then δu = (I − u uᵀ) δw/|w|.
void normal_turning(const Eigen::Vector3d& edge, const Eigen::Vector3d& gap, double s, bool s_free,
                    const Eigen::Vector3d& axis, bool t_free, Eigen::Matrix3d& first,
                    Eigen::Matrix3d& second) {
  const double distance = gap.norm();
  const Eigen::Vector3d u = gap / distance;
  const Eigen::Matrix3d across = (Eigen::Matrix3d::Identity() - u * u.transpose()) / distance;
  for (int node = 0; node < 2; ++node) {
    // δx_i (node 0) or δx_{i+1} (node 1): the point moves by δy = (1 − s) δx_i + s δx_{i+1},
    // the edge by ∓ δx, so w·δe = ∓ wᵀ δx.
    const double share = node == 0 ? 1.0 - s : s;
    const double sign = node == 0 ? -1.0 : 1.0;
    const Eigen::Matrix3d moved = share * Eigen::Matrix3d::Identity();  // δy
    const Eigen::RowVector3d w_edge = sign * gap.transpose();           // w·δe
    Eigen::Matrix3d d_gap = moved;
    if (s_free && t_free) {
      // [e·e  −e·a; a·e  −a·a] (δs, δt) = (−w·δe − e·δy, −a·δy)
      Eigen::Matrix2d system;
      system << edge.dot(edge), -edge.dot(axis), axis.dot(edge), -1.0;
      Eigen::Matrix<double, 2, 3> right;
      right.row(0) = -w_edge - edge.transpose() * moved;
      right.row(1) = -axis.transpose() * moved;
      const Eigen::Matrix<double, 2, 3> z = system.inverse() * right;
      d_gap += edge * z.row(0) - axis * z.row(1);
    } else if (s_free) {
      d_gap += edge * ((-w_edge - edge.transpose() * moved) / edge.squaredNorm());
    } else if (t_free) {
      d_gap -= axis * (axis.transpose() * moved);
    }
    (node == 0 ? first : second) = across * d_gap;
  }
}

}  // namespace

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
  recorded_.reserve(model.n_elements * std::max<int>(1, static_cast<int>(cylinders_.size())));
}

void CylinderContact::start_step(const RodModel&, RodState&, double) { recorded_.start_step(); }

void CylinderContact::add_contact_loads(const RodModel& model, RodState& state) {
  recorded_.clear();
  if (recorded_.deciding()) {
    find_contacts(model, state);
  } else {
    for (int k = 0; k < recorded_.held_count(); ++k) {
      const WallContacts::Held& held = recorded_.held()[k];
      const Cylinder& cylinder = cylinders_[held.wall];
      const ClosestPoints closest = closest_points_between_segments(
          state.positions.col(held.element), state.positions.col(held.element + 1), cylinder.start,
          cylinder.end());
      respond(model, state, held.element, held.wall, closest,
              held.cancels_push ? PushRule::kCancel : PushRule::kLeave);
    }
  }
  contacts_ = recorded_.count();
  recorded_.finish_evaluation();
}

void CylinderContact::find_contacts(const RodModel& model, RodState& state) {
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
  for (std::size_t c = 0; c < cylinders_.size(); ++c) {
    const Cylinder& cylinder = cylinders_[c];
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
      respond(model, state, i, static_cast<int>(c), closest, PushRule::kBySign);
    }
  }
}

void CylinderContact::respond(const RodModel& model, RodState& state, int i, int wall,
                              const ClosestPoints& closest, PushRule rule) {
  const Cylinder& cylinder = cylinders_[wall];
  const Eigen::Vector3d gap = closest.on_first - closest.on_second;
  const double distance = gap.norm();
  if (distance <= 0.0) return;
  const double penetration = state.radii[i] + cylinder.radius - distance;
  const Eigen::Vector3d normal = gap / distance;
  const WallResponse response =
      add_wall_response(wall_, model, state, i, normal, penetration, rule);
  const Eigen::Vector3d edge = state.positions.col(i + 1) - state.positions.col(i);
  const double fraction = std::clamp(
      (closest.on_first - state.positions.col(i)).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
  const double along = (closest.on_second - cylinder.start).dot(cylinder.axis);
  Eigen::Matrix3d turn_first, turn_second;
  normal_turning(
      edge, gap, fraction,
      fraction > 0.0 && fraction<1.0, cylinder.axis, along> 0.0 && along < cylinder.length,
      turn_first, turn_second);
  recorded_.record(i, wall, normal, fraction, turn_first, turn_second, response);
}

void CylinderContact::add_load_derivatives(const RodModel&, const RodState& state,
                                           RodJacobian& jacobian) const {
  recorded_.add_derivatives(wall_, state, jacobian);
}

PlaneContact::PlaneContact(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                           SoftWall wall)
    : point_(point), normal_(normal), wall_(wall) {
  wall_.validate("PlaneContact");
  require(point.allFinite(), "point must be finite", "PlaneContact");
  require(normal.allFinite() && std::abs(normal.norm() - 1.0) < 1e-9, "normal must be a unit vector",
          "PlaneContact");
}

void PlaneContact::attach(const RodModel& model, const RodState&) {
  recorded_.reserve(model.n_elements);
}

void PlaneContact::start_step(const RodModel&, RodState&, double) { recorded_.start_step(); }

void PlaneContact::add_contact_loads(const RodModel& model, RodState& state) {
  const bool deciding = recorded_.deciding();
  recorded_.clear();
  const int count = deciding ? model.n_elements : recorded_.held_count();
  for (int k = 0; k < count; ++k) {
    const int i = deciding ? k : recorded_.held()[k].element;
    const Eigen::Vector3d middle = 0.5 * (state.positions.col(i) + state.positions.col(i + 1));
    const double penetration = state.radii[i] - (middle - point_).dot(normal_);
    if (deciding && penetration < 0.0) continue;
    const PushRule rule = deciding                           ? PushRule::kBySign
                          : recorded_.held()[k].cancels_push ? PushRule::kCancel
                                                             : PushRule::kLeave;
    const WallResponse response =
        add_wall_response(wall_, model, state, i, normal_, penetration, rule);
    recorded_.record(i, 0, normal_, 0.5, Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(),
                     response);
  }
  recorded_.finish_evaluation();
}

void PlaneContact::add_load_derivatives(const RodModel&, const RodState& state,
                                        RodJacobian& jacobian) const {
  recorded_.add_derivatives(wall_, state, jacobian);
}

}  // namespace tendril::physics
