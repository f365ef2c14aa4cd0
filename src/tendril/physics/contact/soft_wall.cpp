#include "tendril/physics/contact/soft_wall.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"

namespace tendril::physics {

void SoftWall::validate(const char* who) const {
  require(std::isfinite(stiffness) && stiffness > 0.0, "wall stiffness must be finite and positive",
          who);
  require(std::isfinite(damping) && damping >= 0.0, "wall damping must be finite and non-negative",
          who);
}

void WallContacts::reserve(int capacity) {
  contacts_.resize(capacity);
  held_.resize(capacity);
  count_ = 0;
  held_count_ = 0;
  deciding_ = true;
}

void WallContacts::record(int element, int wall, const Eigen::Vector3d& normal, double fraction,
                          const Eigen::Matrix3d& normal_change_first,
                          const Eigen::Matrix3d& normal_change_second,
                          const WallResponse& response) {
  // More contacts than reserved are still recorded.
  if (count_ == static_cast<int>(contacts_.size())) contacts_.push_back({});
  contacts_[count_++] = {element, wall, normal, fraction, normal_change_first, normal_change_second,
                         response};
}

void WallContacts::finish_evaluation() {
  if (!deciding_) return;
  if (held_.size() < contacts_.size()) held_.resize(contacts_.size());
  for (int k = 0; k < count_; ++k) {
    held_[k] = {contacts_[k].element, contacts_[k].wall, contacts_[k].response.cancels_push};
  }
  held_count_ = count_;
  deciding_ = false;
}

void WallContacts::add_derivatives(const SoftWall& wall, const RodState& state,
                                   RodJacobian& jacobian) const {
  for (int k = 0; k < count_; ++k) {
    const Contact& c = contacts_[k];
    const Eigen::Vector3d& u = c.normal;
    const WallResponse& response = c.response;
    const Eigen::Vector3d thinning =
        (0.5 * state.radii[c.element] / state.lengths[c.element]) * state.tangents.col(c.element);
    Eigen::Matrix3d d_magnitude_d_normal = response.magnitude * Eigen::Matrix3d::Identity() -
                                           wall.damping * u * response.mean_velocity.transpose();
    if (response.cancels_push) d_magnitude_d_normal -= u * response.element_force.transpose();
    const Eigen::Matrix3d first =
        0.5 * (wall.stiffness * u * (-(1.0 - c.fraction) * u + thinning).transpose() +
               d_magnitude_d_normal * c.normal_change_first);
    const Eigen::Matrix3d second =
        0.5 * (wall.stiffness * u * (-c.fraction * u - thinning).transpose() +
               d_magnitude_d_normal * c.normal_change_second);
    jacobian.add_wall_contact(c.element, u, first, second, wall.damping, response.cancels_push);
  }
}

}  // namespace tendril::physics
