#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace tendril::physics {

// One spring of a mass-spring lattice between nodes `a` and `b`: the force on `a` is
//   f = k (l − L0) ẑ + c ((v_b − v_a)·ẑ) ẑ,   ẑ = (x_b − x_a)/l,
// and −f on `b` (a Hookean spring in N/m with a dashpot along its axis in N·s/m, the damping
// that leaves rigid motion undamped).
struct Spring {
  int a = 0, b = 0;
  double rest_length = 0.0;  // m
  double stiffness = 0.0;    // N/m
  double damping = 0.0;      // N·s/m
};

// The immutable parameters of a planar mass-spring lattice (lab frame, x and y in metres):
// where the nodes rest, what they weigh, which springs join them and which are fixed. The
// state that evolves (positions, velocities, time) is kept apart in LatticeState.
struct LatticeModel {
  Eigen::Matrix2Xd rest_positions;  // m, one column per node
  Eigen::VectorXd masses;           // kg, lumped at the nodes
  std::vector<Spring> springs;
  std::vector<uint8_t> fixed;  // 1: the node never moves (a clamped base)
  // Mass-proportional (Rayleigh α) damping: every free node feels −α m v. 1/s.
  double mass_damping = 0.0;

  int n_nodes() const { return static_cast<int>(rest_positions.cols()); }
  int n_springs() const { return static_cast<int>(springs.size()); }
  // Raises tendril::Error naming `where` and the first invalid value: sizes that disagree,
  // non-finite or non-positive masses of free nodes, springs with a bad node index, a zero
  // rest length, negative stiffness or damping.
  void validate(const std::string& where) const;
};

}  // namespace tendril::physics
