#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/forcing/spline_actuation.hpp"
#include "tendril/physics/rod/rod.hpp"
#include "tendril/physics/rod/rod_lanes.hpp"

namespace tendril::physics {

// Many rods of one model — one RodModel, the same parts with the same parameters — advanced in
// lockstep by position Verlet, each with its own configuration, rates, time and muscle
// targets. The rods sit side by side, the rod index innermost (RodLanes: blocks of kRodLanes),
// so every kernel is vectorized across rods; each block finishes all its steps before the next
// starts, so its arrays stay in cache. So n copies of one arm cost less than n separate Rods
// once n fills a block (bench/rod_pool_bench.cpp: about 1.9× the rate for n = 8 and 64 on an
// AVX-512 core; a lone rod in a block of eight costs four lone Rods).
//
// Every rod reproduces, bit for bit, the positions, velocities, directors and angular
// velocities that a lone Rod built like the prototype would have after the same advance calls
// (Rod merges the half kinematic steps within one call, so the calls must match too): each
// lane's arithmetic is Rod's, expression for expression (rod_lanes.hpp), and rod_pool_test
// checks the equality under the build's compiler settings. Advancing allocates nothing.
//
// Parts mirrored (of the prototype, in its attachment order within each stage):
//   FixedEnd, InternalDamping, AnalyticalLinearDamping, Gravity, EndForces (one set of
//   parameters for all rods, as they are when the pool is built) and at most one
//   SplineActuation (its targets per rod).
// Anything else — contact, tendons, active strain, per-node or per-element loads, general
// constraints, the sensors and actuators of the twins — and implicit integrators raise
// tendril::Error naming the part; there are no silent differences.
//
// Not kept: the read-outs of strains, stresses and radii (Rod::shear_strains, curvatures,
// energies); a rod's snapshot. A rod whose state became non-finite stops advancing (its values
// stay those at the end of the call that made it non-finite, as a Rod's) until set_state.
class RodPool {
 public:
  // `count` copies of `prototype` in its current state (configuration, rates, time and muscle
  // control points). Raises tendril::Error for count < 1, an implicit rod or an unsupported
  // part.
  RodPool(const Rod& prototype, int count);

  int size() const { return count_; }
  const RodModel& model() const { return model_; }
  double time_step() const { return model_.time_step; }

  // Advances every rod that is still finite by `steps` time steps. Returns true if all rods
  // are finite afterwards (see is_finite for which are not).
  [[nodiscard]] bool advance(int steps = 1);
  bool is_finite(int rod) const;

  // The configuration, rates and time of one rod, in and out, in RodState's layout (other
  // fields of `state` are neither read nor written). set_state raises Error if `state` is not
  // sized for the model; it also makes the rod finite again if its values are.
  void set_state(int rod, const RodState& state);
  void get_state(int rod, RodState& state) const;
  Eigen::Vector3d node_position(int rod, int node) const;
  Eigen::Vector3d tip_position(int rod) const { return node_position(rod, model_.n_elements); }
  Eigen::Vector3d tip_velocity(int rod) const;
  double time(int rod) const;

  // The muscles of one rod (SplineActuation::set_targets semantics: clamped to [−1, 1], rate
  // limited per step if the prototype's are). Raise Error if the prototype has none.
  bool has_muscles() const { return !muscles_.empty(); }
  void set_targets(int rod, const Eigen::VectorXd& targets);
  const SplineActuation& muscles(int rod) const;

 private:
  enum class LoadKind { kInternalDamping, kMuscles, kGravity, kEndForces };
  struct Load {
    LoadKind kind;
    double coefficient = 0.0;                          // ν of InternalDamping
    Eigen::Vector3d first = Eigen::Vector3d::Zero();   // g, or the start force
    Eigen::Vector3d second = Eigen::Vector3d::Zero();  // the end force
    double ramp_time = 0.0;
  };
  struct Clamp {
    Eigen::Vector3d position;
    Eigen::Matrix3d directors;
  };
  struct RateDamping {
    Eigen::VectorXd velocity_factors;  // per node
    Vectors angular_factors;           // per element and material axis
  };

  void mirror(const RodPart& part, int index);
  void check_rod(int rod, const char* who) const;
  void step_block(int block, int steps);
  void scatter_couples(int rod);
  void constrain_values(RodLanes& lanes) const;
  void add_loads(RodLanes& lanes) const;
  void constrain_and_damp_rates(RodLanes& lanes) const;

  RodModel model_;
  int count_;
  std::vector<RodLanes> blocks_;
  std::vector<char> finite_;
  // Parts by stage, each list in the prototype's attachment order.
  std::vector<Clamp> clamps_;
  std::vector<Load> loads_;
  std::vector<RateDamping> rate_dampings_;
  std::vector<SplineActuation> muscles_;  // one per rod; empty without muscles
  bool muscles_rate_limited_ = false;
  RodState scratch_;  // what SplineActuation::start_step is handed (it reads nothing of it)
  RodLanes stopped_;  // the values of stopped rods while their block advances
};

}  // namespace tendril::physics
