#pragma once

#include <Eigen/Core>
#include <array>

#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// Rods of one model side by side in a RodPool: kRodLanes of them per block, so that every loop
// over the lanes is one or two vector instructions wide and one block's arrays stay in the
// core's second-level cache (74 kB for the 20-element arm).
constexpr int kRodLanes = 8;

// Per-node or per-element quantities of kRodLanes rods, the rod index innermost: column
// k · count + i holds component k of node (or element) i of every lane, contiguously.
using LaneColumns = Eigen::Matrix<double, kRodLanes, Eigen::Dynamic>;
using LaneMask = std::array<bool, kRodLanes>;

// The state of kRodLanes rods of one model in the layout above, and the scratch of the
// internal-load kernel. Holds what position Verlet needs and nothing a read-out alone would
// (no radii, strains or stresses are kept).
struct RodLanes {
  // Configuration and rates, as in RodState: x, v (lab, n + 1), Q (rows d1 d2 d3, 9 × n),
  // ω (material, n); time per lane (one column).
  LaneColumns positions, velocities, directors, angular_velocities, time;
  // Loads added by parts this step: forces (lab, n + 1), torques (material, n).
  LaneColumns external_forces, external_torques;
  // Material-frame couples of the lanes' muscles (3 × n; zero without muscles).
  LaneColumns muscle_couples;

  // Derived in internal_loads.
  LaneColumns lengths, dilatations;      // n
  LaneColumns lab_stresses;              // Qᵀ n / e, 3 × n
  LaneColumns curvatures;                // κ (first sin θ · axis), 3 × (n − 1)
  LaneColumns cosines, factors;          // cos θ and θ / sin θ, n − 1
  LaneColumns bend_couples, quadrature;  // τ / ε³ and ½ (κ × τ) D̂ / ε³, 3 × (n − 1)
  LaneColumns internal_forces;           // lab, 3 × (n + 1)
  LaneColumns internal_torques;          // material, 3 × n
  LaneColumns saved_directors;           // Q before a kinematic step, 9 × n

  int n_elements = 0;

  void resize(const RodModel& model);

  // The lanes of component k of node or element i of an array with `count` columns per
  // component.
  static double* at(LaneColumns& array, int count, int k, int i) {
    return array.data() + (static_cast<Eigen::Index>(k) * count + i) * kRodLanes;
  }
  static const double* at(const LaneColumns& array, int count, int k, int i) {
    return array.data() + (static_cast<Eigen::Index>(k) * count + i) * kRodLanes;
  }

  // Copies the configuration, rates and time of `state` into `lane`, and back.
  void set_lane(int lane, const RodState& state);
  void get_lane(int lane, RodState& state) const;
  // Whether every position, velocity, director and angular velocity of each lane is finite.
  LaneMask finite_lanes() const;
};

// The kernels of Rod's position-Verlet step, each lane's arithmetic exactly that of Rod for one
// rod (same expressions in the same order), so that a lane reproduces a lone Rod bit for bit.
// `active` names the lanes whose rare branches (large rotations, large frame angles) are taken
// with Rod's general formulas; the others run the common path only.

// x += h v;  Q ← exp(−h [ω]×) Q.
void lanes_kinematic_step(const RodModel& model, RodLanes& lanes, double h, const LaneMask& active);
// Rod's compute_internal_loads: internal forces (lab, per node) and torques (material, per
// element), with the lengths and dilatations that parts read.
void lanes_internal_loads(const RodModel& model, RodLanes& lanes, const LaneMask& active);
// m dv/dt = F_internal + F_external;  (J/e) dω/dt = T_internal + T_external.
void lanes_dynamic_step(const RodModel& model, RodLanes& lanes, double dt);

}  // namespace tendril::physics
