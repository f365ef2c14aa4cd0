#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/contact/cylinder_contact.hpp"
#include "tendril/physics/forcing/spline_actuation.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {

// The soft arm of the Elastica RL paper (Naughton et al. 2021, Tables 6–7; SPEC M2): L 1 m,
// radius 5 cm, E 10 MPa, ρ 1000 kg/m³, G = E / (1 + 0.5), α_c = 4/3, base clamped, paper-era
// internal damping ν = 30 kg/(m·s), spline muscle couples on every element (material frame).
struct ElasticaArmSpec {
  int n_elements = 20;
  double time_step = 2.0e-4;  // s, the paper's position-Verlet step
  // How the rod advances: the paper's position Verlet at time_step, or an implicit integrator
  // (RodIntegrator) at implicit_step; the muscles' rate limit then keeps its rate per second.
  RodIntegrator integrator = RodIntegrator::kPositionVerlet;
  double implicit_step = 1.4e-3;  // s, one step per RL action of the four cases
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double damping = 30.0;
  SplineActuationSpec actuation;    // case 1: 6 normal + 6 binormal control points
  std::vector<Cylinder> obstacles;  // soft-wall contact with k 8e4, γ 4 when non-empty
  SoftWall wall{8.0e4, 4.0, true};

  // Cases 1–2: 20 elements, dt 0.2 ms, base at the origin along +y, normal +z.
  static ElasticaArmSpec tracking();
  // Case 3: 50 elements, dt 0.1 ms, base (0, 0.5, 0) along +z, normal +y, the wall of eight
  // cylinders (radius 0.1 m, length 1 m, axis +y from y = 0) with one 0.17 m gap, and two normal
  // control points whose change is limited to 0.01 per step.
  static ElasticaArmSpec structured_obstacles();
};

struct ElasticaArm {
  Rod rod;
  SplineActuation* muscles;   // owned by `rod`
  CylinderContact* contact;   // owned by `rod`; null without obstacles
};

ElasticaArm build_elastica_arm(const ElasticaArmSpec& spec);

}  // namespace tendril::physics
