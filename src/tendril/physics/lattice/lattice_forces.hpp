#pragma once

#include <Eigen/Core>

#include "tendril/physics/lattice/lattice_model.hpp"

namespace tendril::physics {

// Adds the lattice's internal forces at positions `x` and velocities `v` (m, m/s; one column
// per node) to `forces` (N): every spring's Hookean force and axial dashpot (Spring), and the
// mass-proportional damping −α m v on free nodes. Forces on fixed nodes are added too (they are
// the reactions); integrators ignore them.
void add_internal_forces(const LatticeModel& model, const Eigen::Matrix2Xd& x,
                         const Eigen::Matrix2Xd& v, Eigen::Matrix2Xd& forces);

// Σ ½ k (l − L0)² over the springs, J.
double elastic_energy(const LatticeModel& model, const Eigen::Matrix2Xd& x);

// Σ ½ m v² over the free nodes, J.
double kinetic_energy(const LatticeModel& model, const Eigen::Matrix2Xd& v);

}  // namespace tendril::physics
