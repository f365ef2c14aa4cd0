#include "tendril/physics/rod/rod_model.hpp"

#include <cmath>
#include <numbers>

namespace tendril::physics {

RodModel RodModel::build(const RodSpec& spec) {
  spec.validate();
  const int n = spec.n_elements;
  RodModel m;
  m.n_elements = n;
  m.time_step = spec.time_step;
  m.density = spec.density;
  m.youngs_modulus = spec.youngs_modulus;
  m.shear_modulus = spec.shear_modulus;

  m.rest_lengths = Eigen::VectorXd::Constant(n, spec.length / n);
  m.rest_radii = Eigen::VectorXd::Constant(n, spec.radius);
  m.rest_areas = std::numbers::pi * m.rest_radii.array().square();
  m.rest_voronoi_lengths.resize(std::max(n - 1, 0));
  for (int j = 0; j + 1 < n; ++j) {
    m.rest_voronoi_lengths[j] = 0.5 * (m.rest_lengths[j] + m.rest_lengths[j + 1]);
  }
  m.rest_shear_strains = Vectors::Zero(3, n);
  m.rest_curvatures = spec.rest_curvature.replicate(1, std::max(n - 1, 0));

  m.shear_stiffness.resize(3, n);
  m.inertia.resize(3, n);
  Vectors element_bend(3, n);
  m.node_masses = Eigen::VectorXd::Zero(n + 1);
  for (int i = 0; i < n; ++i) {
    const double area = m.rest_areas[i];
    const double i1 = area * area / (4.0 * std::numbers::pi);  // π r⁴ / 4
    const Eigen::Vector3d second_moments(i1, i1, 2.0 * i1);
    m.shear_stiffness.col(i) << spec.shear_coefficient * spec.shear_modulus * area,
        spec.shear_coefficient * spec.shear_modulus * area, spec.youngs_modulus * area;
    element_bend.col(i) << spec.youngs_modulus * second_moments.x(),
        spec.youngs_modulus * second_moments.y(), spec.shear_modulus * second_moments.z();
    m.inertia.col(i) =
        spec.rotary_inertia_scale * spec.density * m.rest_lengths[i] * second_moments;
    const double element_mass = spec.density * area * m.rest_lengths[i];
    m.node_masses[i] += 0.5 * element_mass;
    m.node_masses[i + 1] += 0.5 * element_mass;
  }
  m.node_masses[n] += spec.tip_mass;
  m.inverse_node_masses = m.node_masses.cwiseInverse();
  m.inverse_inertia = m.inertia.cwiseInverse();

  m.bend_stiffness.resize(3, std::max(n - 1, 0));
  for (int j = 0; j + 1 < n; ++j) {
    const double lj = m.rest_lengths[j], lk = m.rest_lengths[j + 1];
    m.bend_stiffness.col(j) = (element_bend.col(j) * lj + element_bend.col(j + 1) * lk) / (lj + lk);
  }
  return m;
}

}  // namespace tendril::physics
