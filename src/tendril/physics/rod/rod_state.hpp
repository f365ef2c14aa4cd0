#pragma once

#include <Eigen/Core>

#include "tendril/physics/rod/rod_model.hpp"

namespace tendril::physics {

// The mutable part of a discrete Cosserat rod: its configuration and rates, the loads that
// parts add each step, and the quantities the internal-load kernel derives from the
// configuration (read by parts such as contact, and by read-outs). Sized once by `resize`;
// stepping never allocates.
struct RodState {
  // Configuration and rates.
  Vectors positions;                  // x, lab frame, m, n + 1
  Vectors velocities;                 // v, lab frame, m/s, n + 1
  Frames directors;                            // Q, rows d1 d2 d3 (lab → material), n
  Vectors angular_velocities;         // ω, material frame, rad/s, n
  double time = 0.0;                           // s

  // Loads added by parts in the current step.
  Vectors external_forces;   // lab frame, N, n + 1
  Vectors external_torques;  // material frame, N·m, n

  // Derived from the configuration by compute_internal_loads().
  Eigen::VectorXd lengths;              // l_i, m
  Vectors tangents;            // t_i, lab frame, unit
  Eigen::VectorXd dilatations;          // e_i = l_i / l̂_i
  Eigen::VectorXd dilatation_rates;     // de_i/dt, 1/s
  Eigen::VectorXd radii;                // r_i = r̂_i / √e_i (volume conservation), m
  Eigen::VectorXd voronoi_dilatations;  // ε_j = D_j / D̂_j
  Vectors shear_strains;       // σ_i = e_i Q_i t_i − d3, material frame
  Vectors internal_stresses;   // n_i = S_i (σ_i − σ̂_i), material frame, N
  Vectors curvatures;          // κ_j, material frame, 1/m
  Vectors internal_couples;    // τ_j = B_j (κ_j − κ̂_j), material frame, N·m
  Vectors internal_forces;     // lab frame, N, n + 1
  Vectors internal_torques;    // material frame, N·m, n

  // Scratch of the internal-load kernel (per element / per Voronoi point).
  Vectors element_lab_stresses;   // Qᵀ n / e, lab frame
  Vectors voronoi_bend_couples;   // τ / ε³
  Vectors voronoi_quadrature;     // ½ (κ × τ) D̂ / ε³
  Eigen::VectorXd voronoi_cosines;  // cos of the angle between neighbouring frames
  Eigen::VectorXd voronoi_factors;  // θ / sin θ of that angle

  void resize(const RodModel& model);

  Eigen::Matrix3d director(int i) const {
    Eigen::Matrix3d q;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) q(r, c) = directors(3 * r + c, i);
    }
    return q;
  }
  void set_director(int i, const Eigen::Matrix3d& q) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) directors(3 * r + c, i) = q(r, c);
    }
  }
};

}  // namespace tendril::physics
