#pragma once

#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs::beam {

inline constexpr double kTaskMassDamping = 5.0;  // 1/s, Rayleigh α of the tasks' beam

// The four tasks of seed 003 (Suryadevara; SPEC M4), built from an experiment's env.params.
// Every parameter is optional; each task's defaults are the seed's set-up, and where the seed
// is silent the choices of docs/results/beam.md (all in BeamTaskSpec, BeamLatticeSpec,
// ArcSpec, EllipseSpec).
//
// Common parameters:
//   torque_scale (N·m per unit action), control_period (s), observation (tip | six_points |
//   trajectory), distance_weight, velocity_weight, energy_weight, energy_units (newton_metres |
//   normalised), max_distance (m, 0 = off), success_distance (m), nan_penalty;
//   the beam's numerics and damping: integrator (bdf2 | backward_euler | symplectic_euler),
//   time_step (s), newton_iterations, mass_damping (1/s), stiffness_damping (s).
// The tasks' beam is damped at mass_damping = 5 s⁻¹ (kTaskMassDamping; the seed gives no
// damping): at the lattice's default 1 s⁻¹ the first bending mode (ω ≈ 2.9 rad/s, ζ ≈ 0.17)
// rings for several periods after every change of torque and SAC did not learn to follow the
// arcs in 200k steps; at 5 s⁻¹ (ζ ≈ 0.87 in that mode) it does (docs/results/beam.md).
// Arc tasks: radius, angular_velocity ([low, high], m and rad/s), arc_angle (degrees),
//   mean_reversal_interval (s), or levels: [{radius: [..], angular_velocity: [..]}, ...].
// Ellipse: semi_major_axis, eccentricity, angular_velocity ([low, high]: the last level; the
//   first two are built around it, EllipseSpec::default_levels), top (m), or levels:
//   [{semi_major_axis: [..], eccentricity: [..], angular_velocity: [..]}, ...].
// Any task with more than one level can be given curriculum: {...} (envs::Curriculum).

// Beam/ArcFollow-v0 — Task 1, path following (Sec. IV): 160° arcs of radius 0.2–0.6 m at
// 0.5 rad/s with random reversals; Model 1 state (tip, 4), reward −20 r_d; ±4.5 N·m.
// observation: six_points gives Model 2 (14).
std::unique_ptr<Env> make_arc_follow(const Config& params);
EnvDescription arc_follow_description();
// Beam/TrajectoryFollow-v0 — Task 2 (Sec. V): the arcs at ω ∈ [0.1, 0.5] rad/s, Model 3 state
// (18), reward −40 r_d − 10 r_v (case 2, the seed's best; cases 1 and 3 by the weights).
std::unique_ptr<Env> make_trajectory_follow(const Config& params);
EnvDescription trajectory_follow_description();
// Beam/EnergyAwareFollow-v0 — Task 3 (Sec. VI): Task 2 with −1 · |Σ τ_i θ_i| added.
std::unique_ptr<Env> make_energy_aware_follow(const Config& params);
EnvDescription energy_aware_follow_description();
// Beam/EllipseFollow-v0 — Task 4 (Sec. VII): the ellipse, Model 3 state and case-2 reward,
// ±8 N·m, three levels from fixed parameters to the seed's ranges.
std::unique_ptr<Env> make_ellipse_follow(const Config& params);
EnvDescription ellipse_follow_description();

// Registered time limits: 10 s of 50 ms steps (a 160° arc at 0.5 rad/s takes 5.6 s), and for
// the ellipse 13 s, one revolution at its slowest ω (2π / 0.5 rad/s = 12.6 s).
inline constexpr int kArcEpisodeSteps = 200;
inline constexpr int kEllipseEpisodeSteps = 260;

}  // namespace tendril::envs::beam
