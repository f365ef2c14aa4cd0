#include "tendril/physics/twins/pneumatic/mass_eccentricity.hpp"

#include <Eigen/Geometry>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"
#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics::pneumatic {

MassEccentricity::MassEccentricity(Vectors offsets, const Eigen::Vector3d& gravity)
    : offsets_(std::move(offsets)), gravity_(gravity) {
  require(offsets_.allFinite() && gravity_.allFinite(), "offsets and gravity must be finite",
          "MassEccentricity");
}

void MassEccentricity::attach(const RodModel& model, const RodState&) {
  if (offsets_.cols() != model.n_elements) {
    throw Error("got " + std::to_string(offsets_.cols()) + " offsets for a rod of " +
                    std::to_string(model.n_elements) + " elements",
                "MassEccentricity");
  }
  masses_ = model.density * model.rest_areas.cwiseProduct(model.rest_lengths);
}

void MassEccentricity::add_loads(const RodModel& model, RodState& state) {
  for (int i = 0; i < model.n_elements; ++i) {
    const Eigen::Vector3d weight = state.director(i) * (masses_[i] * gravity_);
    const Eigen::Vector3d offset(offsets_(0, i), offsets_(1, i), 0.0);
    state.external_torques.col(i) += offset.cross(weight);
  }
}

void MassEccentricity::add_load_derivatives(const RodModel& model, const RodState& state,
                                            RodJacobian& jacobian) const {
  for (int i = 0; i < model.n_elements; ++i) {
    const Eigen::Vector3d weight = state.director(i) * (masses_[i] * gravity_);
    const Eigen::Vector3d offset(offsets_(0, i), offsets_(1, i), 0.0);
    const int self = RodJacobian::element(i);
    jacobian.add_stiffness(self, self, skew(offset) * skew(weight));
  }
}

}  // namespace tendril::physics::pneumatic
