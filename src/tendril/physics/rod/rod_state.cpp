#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

void RodState::resize(const RodModel& model) {
  const int n = model.n_elements, nodes = model.n_nodes(), voronoi = model.n_voronoi();
  positions = Vectors::Zero(3, nodes);
  velocities = Vectors::Zero(3, nodes);
  directors = Frames::Zero(9, n);
  for (int i = 0; i < n; ++i) set_director(i, Eigen::Matrix3d::Identity());
  angular_velocities = Vectors::Zero(3, n);
  external_forces = Vectors::Zero(3, nodes);
  external_torques = Vectors::Zero(3, n);
  lengths = Eigen::VectorXd::Zero(n);
  tangents = Vectors::Zero(3, n);
  dilatations = Eigen::VectorXd::Ones(n);
  dilatation_rates = Eigen::VectorXd::Zero(n);
  radii = model.rest_radii;
  voronoi_dilatations = Eigen::VectorXd::Ones(voronoi);
  shear_strains = Vectors::Zero(3, n);
  internal_stresses = Vectors::Zero(3, n);
  curvatures = Vectors::Zero(3, voronoi);
  internal_couples = Vectors::Zero(3, voronoi);
  internal_forces = Vectors::Zero(3, nodes);
  internal_torques = Vectors::Zero(3, n);
  element_lab_stresses = Vectors::Zero(3, n);
  voronoi_bend_couples = Vectors::Zero(3, voronoi);
  voronoi_quadrature = Vectors::Zero(3, voronoi);
  voronoi_cosines = Eigen::VectorXd::Ones(voronoi);
  voronoi_factors = Eigen::VectorXd::Ones(voronoi);
}

}  // namespace tendril::physics
