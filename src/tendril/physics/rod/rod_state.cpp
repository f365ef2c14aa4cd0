#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

void RodState::resize(const RodModel& model) {
  const int n = model.n_elements, nodes = model.n_nodes(), voronoi = model.n_voronoi();
  positions = Eigen::Matrix3Xd::Zero(3, nodes);
  velocities = Eigen::Matrix3Xd::Zero(3, nodes);
  directors.assign(n, Eigen::Matrix3d::Identity());
  angular_velocities = Eigen::Matrix3Xd::Zero(3, n);
  external_forces = Eigen::Matrix3Xd::Zero(3, nodes);
  external_torques = Eigen::Matrix3Xd::Zero(3, n);
  lengths = Eigen::VectorXd::Zero(n);
  tangents = Eigen::Matrix3Xd::Zero(3, n);
  dilatations = Eigen::VectorXd::Ones(n);
  dilatation_rates = Eigen::VectorXd::Zero(n);
  radii = model.rest_radii;
  voronoi_dilatations = Eigen::VectorXd::Ones(voronoi);
  shear_strains = Eigen::Matrix3Xd::Zero(3, n);
  internal_stresses = Eigen::Matrix3Xd::Zero(3, n);
  curvatures = Eigen::Matrix3Xd::Zero(3, voronoi);
  internal_couples = Eigen::Matrix3Xd::Zero(3, voronoi);
  internal_forces = Eigen::Matrix3Xd::Zero(3, nodes);
  internal_torques = Eigen::Matrix3Xd::Zero(3, n);
}

}  // namespace tendril::physics
