#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/lattice/lattice.hpp"
#include "tendril/physics/lattice/row_couples.hpp"

namespace tendril::physics {

// Seed 003's soft beam (Suryadevara, Sec. III-A): a planar mass-spring lattice of `rows` ×
// `columns` nodes on a regular grid, `width` along x and `length` along y, the base row
// (y = 0) clamped, the beam pointing along +y, centred on x = 0. Units SI, lab frame.
//
// Springs of Vega's quad-mesh mass-spring model, the seed's "tensile / shear / bending
// stiffness":
//   tensile — every quad edge: (columns − 1)·rows across + columns·(rows − 1) along
//             = 62 + 90 = 152 for 3 × 31;
//   shear   — both diagonals of every quad: 2 (rows − 1)(columns − 1) = 120;
//   bending — skip-one neighbours along rows and columns, 31 + 87 = 118, built only when
//             bending_stiffness > 0 (the seed's is 0).
// 272 springs act. The seed's table says "Number of Edges 360": that is 60 quads × 6 (4 edges +
// 2 diagonals each), counting every shared edge twice — a counting convention, not 360 springs.
//
// Masses: surface_density × quad area, a quarter to each corner of each quad (total
// 60 kg/m² × 0.0375 m² = 2.25 kg; interior node 0.0375 kg, edge 0.01875, corner 0.009375).
// Gravity is left out: the tasks are planar and Vega's would act along the beam's axis.
//
// Damping (the seed gives none): Rayleigh damping C = α M + β K₀ of the springs' axial
// stiffness, i.e. −α m v on every node and a dashpot c = β k along every spring. α = 1 s⁻¹ and
// β = 1e-3 s (the suggested values) damp the first bending mode (ω ≈ 2.9 rad/s) at ζ ≈ 0.17,
// the second and third (≈ 18, 50 rad/s) at ζ ≈ 0.035, and the lattice's stiff in-plane
// vibrations (10³ rad/s and up) at ζ ≥ 0.5.
//
// Torques: one RowCouples pair per entry of `torque_rows` (0-based row indices), on the row's
// outer nodes. The seed's groups "nodes 16–18, 34–36, 52–54, 70–72, 88–90" (1-based, three per
// row) are rows 6, 12, 18, 24, 30 counted from 1, i.e. 5, 11, 17, 23, 29 here, at y = 0.125 …
// 0.725 m; the tip row is 30 (y = 0.75).
struct BeamLatticeSpec {
  int rows = 31;
  int columns = 3;
  double width = 0.05;                 // m
  double length = 0.75;                // m
  double surface_density = 60.0;       // kg/m²
  double tensile_stiffness = 18750.0;  // N/m
  double shear_stiffness = 18750.0;    // N/m
  double bending_stiffness = 0.0;      // N/m
  double mass_damping = 1.0;           // 1/s, Rayleigh α
  double stiffness_damping = 1.0e-3;   // s, Rayleigh β
  std::vector<int> torque_rows = {5, 11, 17, 23, 29};
  // BDF2 at 10 ms, one Newton iteration: five solves per 50 ms control period (see
  // LatticeIntegrator; its accuracy is checked in beam_dynamics_test).
  LatticeNumerics numerics{LatticeIntegrator::kBdf2, 0.01, 1};

  // Raises tendril::Error("<field> …", "BeamLatticeSpec") for the first invalid field.
  void validate() const;
  int node(int row, int column) const { return row * columns + column; }
};

// The lattice model of `spec` (validated first).
LatticeModel build_beam_model(const BeamLatticeSpec& spec);

// The beam with its couples attached, and the read-outs the tasks use (lab frame, SI).
class BeamLattice {
 public:
  explicit BeamLattice(const BeamLatticeSpec& spec);

  const BeamLatticeSpec& spec() const { return spec_; }
  Lattice& lattice() { return lattice_; }
  const Lattice& lattice() const { return lattice_; }
  RowCouples& couples() { return *couples_; }
  const RowCouples& couples() const { return *couples_; }

  // Centroid of a row's nodes and its velocity; the tip is the last row's.
  Eigen::Vector2d row_centre(int row) const;
  Eigen::Vector2d row_velocity(int row) const;
  Eigen::Vector2d tip_position() const { return row_centre(spec_.rows - 1); }
  Eigen::Vector2d tip_velocity() const { return row_velocity(spec_.rows - 1); }
  // Rotation of a row (outer-left → outer-right node) from its rest direction +x, rad,
  // counter-clockwise positive, unwrapped: the sum of the rotations between consecutive rows
  // from the clamped base, each within (−π, π], so a beam curled past half a turn reads more
  // than π.
  double row_angle(int row) const;
  // Quads whose signed area (corners counter-clockwise at rest) is negative: cells turned
  // inside out. A lattice without bending springs folds this way when the moment it carries
  // compresses its outer columns by ~40 % or more (about 10 N·m at the base), which the seed's
  // torque range allows; the state stays finite, so this is how the collapse is seen.
  int inverted_cells() const;

 private:
  BeamLatticeSpec spec_;
  Lattice lattice_;
  RowCouples* couples_;
};

}  // namespace tendril::physics
