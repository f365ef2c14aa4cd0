#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/rod/rod_model.hpp"

namespace tendril::physics {

// The mutable part of a discrete Cosserat rod: its configuration and rates, the loads that
// parts add each step, and the quantities the internal-load kernel derives from the
// configuration (read by parts such as contact, and by read-outs). Sized once by `resize`;
// stepping never allocates.
struct RodState {
  // Configuration and rates.
  Eigen::Matrix3Xd positions;                  // x, lab frame, m, n + 1
  Eigen::Matrix3Xd velocities;                 // v, lab frame, m/s, n + 1
  std::vector<Eigen::Matrix3d> directors;      // Q, rows d1 d2 d3 (lab → material), n
  Eigen::Matrix3Xd angular_velocities;         // ω, material frame, rad/s, n
  double time = 0.0;                           // s

  // Loads added by parts in the current step.
  Eigen::Matrix3Xd external_forces;   // lab frame, N, n + 1
  Eigen::Matrix3Xd external_torques;  // material frame, N·m, n

  // Derived from the configuration by compute_internal_loads().
  Eigen::VectorXd lengths;              // l_i, m
  Eigen::Matrix3Xd tangents;            // t_i, lab frame, unit
  Eigen::VectorXd dilatations;          // e_i = l_i / l̂_i
  Eigen::VectorXd dilatation_rates;     // de_i/dt, 1/s
  Eigen::VectorXd radii;                // r_i = r̂_i / √e_i (volume conservation), m
  Eigen::VectorXd voronoi_dilatations;  // ε_j = D_j / D̂_j
  Eigen::Matrix3Xd shear_strains;       // σ_i = e_i Q_i t_i − d3, material frame
  Eigen::Matrix3Xd internal_stresses;   // n_i = S_i (σ_i − σ̂_i), material frame, N
  Eigen::Matrix3Xd curvatures;          // κ_j, material frame, 1/m
  Eigen::Matrix3Xd internal_couples;    // τ_j = B_j (κ_j − κ̂_j), material frame, N·m
  Eigen::Matrix3Xd internal_forces;     // lab frame, N, n + 1
  Eigen::Matrix3Xd internal_torques;    // material frame, N·m, n

  void resize(const RodModel& model);
};

}  // namespace tendril::physics
