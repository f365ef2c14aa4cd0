#include "tendril/physics/lattice/lattice_forces.hpp"

namespace tendril::physics {

void add_internal_forces(const LatticeModel& model, const Eigen::Matrix2Xd& x,
                         const Eigen::Matrix2Xd& v, Eigen::Matrix2Xd& forces) {
  for (const Spring& spring : model.springs) {
    const Eigen::Vector2d d = x.col(spring.b) - x.col(spring.a);
    const double length = d.norm();
    const Eigen::Vector2d axis = d / length;
    const double stretch_rate = (v.col(spring.b) - v.col(spring.a)).dot(axis);
    const Eigen::Vector2d f =
        (spring.stiffness * (length - spring.rest_length) + spring.damping * stretch_rate) * axis;
    forces.col(spring.a) += f;
    forces.col(spring.b) -= f;
  }
  if (model.mass_damping > 0.0) {
    for (int i = 0; i < model.n_nodes(); ++i) {
      if (!model.fixed[i]) forces.col(i) -= model.mass_damping * model.masses[i] * v.col(i);
    }
  }
}

double elastic_energy(const LatticeModel& model, const Eigen::Matrix2Xd& x) {
  double energy = 0.0;
  for (const Spring& spring : model.springs) {
    const double stretch = (x.col(spring.b) - x.col(spring.a)).norm() - spring.rest_length;
    energy += 0.5 * spring.stiffness * stretch * stretch;
  }
  return energy;
}

double kinetic_energy(const LatticeModel& model, const Eigen::Matrix2Xd& v) {
  double energy = 0.0;
  for (int i = 0; i < model.n_nodes(); ++i) {
    if (!model.fixed[i]) energy += 0.5 * model.masses[i] * v.col(i).squaredNorm();
  }
  return energy;
}

}  // namespace tendril::physics
