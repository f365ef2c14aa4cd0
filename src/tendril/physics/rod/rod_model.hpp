#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/rod/rod_spec.hpp"

namespace tendril::physics {

// Per-element (or per-node) 3-vectors stored component-major: row k holds component k of every
// element contiguously, so the rod kernels vectorize across elements. Column i is element i.
using Vectors = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
// Per-element 3×3 frames, component-major: row 3r + c holds Q(r, c) of every element.
using Frames = Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::RowMajor>;

// The immutable part of a discrete Cosserat rod (Gazzola et al. 2018, §3): rest geometry,
// stiffness and inertia. n elements between n + 1 nodes; n − 1 interior Voronoi points, point j
// sitting between elements j and j + 1. Diagonal matrices are stored as their diagonals.
struct RodModel {
  int n_elements = 0;
  double time_step = 0.0;

  Eigen::VectorXd rest_lengths;          // l̂_i, n
  Eigen::VectorXd rest_voronoi_lengths;  // D̂_j = (l̂_j + l̂_{j+1}) / 2, n − 1
  Eigen::VectorXd rest_radii;            // r̂_i, n
  Eigen::VectorXd rest_areas;            // Â_i = π r̂_i², n
  Vectors rest_shear_strains;   // σ̂_i, material frame, n
  Vectors rest_curvatures;      // κ̂_j, material frame, 1/m, n − 1

  Vectors shear_stiffness;  // diag S_i = (α_c G Â, α_c G Â, E Â), N, n
  Vectors bend_stiffness;   // diag B_j = (E I1, E I2, G I3) averaged onto Voronoi by l̂, N·m², n − 1

  Eigen::VectorXd node_masses;                 // kg, n + 1 (each element's mass split to its nodes)
  Eigen::VectorXd inverse_node_masses;         // 1/kg, n + 1
  Vectors inertia;                    // diag J_i = ρ l̂ (I1, I2, I3), kg·m², n
  Vectors inverse_inertia;            // diag J_i⁻¹, n

  double density = 0.0;
  double youngs_modulus = 0.0;
  double shear_modulus = 0.0;

  static RodModel build(const RodSpec& spec);
  int n_nodes() const { return n_elements + 1; }
  int n_voronoi() const { return n_elements - 1; }
};

}  // namespace tendril::physics
