#pragma once

#include <array>
#include <numbers>

namespace tendril::physics::ur5 {

// The published parameters of the Universal Robots UR5 (CB-series), SI units.
//
// Kinematics: standard (distal) Denavit–Hartenberg parameters from Universal Robots' "DH
// parameters for calculations of kinematics and dynamics", link i from frame i−1 to frame i:
//   ᶦ⁻¹Tᵢ = Rz(θᵢ) · Tz(dᵢ) · Tx(aᵢ) · Rx(αᵢ),  θᵢ = qᵢ (no joint offsets).
// At q = 0 the flange (frame 6) is at (−0.81725, −0.19145, −0.005491) m in the base frame.
//
// Dynamics: link masses as in Universal Robots' ur_description (shoulder 3.7, upper arm 8.393,
// forearm 2.275, wrists 1.219, 1.219, 0.1879 kg) and centres of mass in each link's own DH
// frame i from the same DH page. The published page gives no inertia tensors; the model
// approximates each link by a solid cylinder (ur5_mjcf.hpp), as ur_description does.
//
// Limits: ±2π on every joint but the elbow (±π, so the arm cannot fold through itself);
// maximum joint speed π rad/s; maximum joint torques 150 N·m (base, shoulder, elbow) and
// 28 N·m (wrists), from the UR5 data sheet.
inline constexpr int kJoints = 6;

inline constexpr std::array<double, kJoints> kDhA = {0.0, -0.425, -0.39225, 0.0, 0.0, 0.0};
inline constexpr std::array<double, kJoints> kDhD = {0.089159, 0.0, 0.0, 0.10915, 0.09465, 0.0823};
inline constexpr std::array<double, kJoints> kDhAlpha = {
    std::numbers::pi / 2, 0.0, 0.0, std::numbers::pi / 2, -std::numbers::pi / 2, 0.0};

inline constexpr std::array<double, kJoints> kLinkMass = {3.7, 8.393, 2.275, 1.219, 1.219, 0.1879};
// Centre of mass of link i in DH frame i (m).
inline constexpr std::array<std::array<double, 3>, kJoints> kLinkCentreOfMass = {{
    {0.0, -0.02561, 0.00193},
    {0.2125, 0.0, 0.11336},
    {0.15, 0.0, 0.0265},
    {0.0, -0.0018, 0.01634},
    {0.0, 0.0018, 0.01634},
    {0.0, 0.0, -0.001159},
}};

inline constexpr std::array<double, kJoints> kJointUpper = {
    2 * std::numbers::pi, 2 * std::numbers::pi, std::numbers::pi,
    2 * std::numbers::pi, 2 * std::numbers::pi, 2 * std::numbers::pi};
inline constexpr double kMaxJointSpeed = std::numbers::pi;  // rad/s
inline constexpr std::array<double, kJoints> kMaxTorque = {150.0, 150.0, 150.0, 28.0, 28.0, 28.0};

// Lateral offsets of the physical links along the parallel shoulder/elbow/wrist-1 axes (m),
// from ur_description: the upper arm sits 0.13585 m out along the shoulder axis, the forearm
// 0.1197 m back, and wrist 1 → wrist 2 adds 0.093 m; 0.13585 − 0.1197 + 0.093 = d₄. The DH
// model folds them into d₄; the collision geometry places the links where they are.
inline constexpr double kUpperArmOffset = 0.13585;
inline constexpr double kForearmOffset = 0.13585 - 0.1197;

// Joint names, base first, as in ur_description.
inline constexpr std::array<const char*, kJoints> kJointNames = {
    "shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3"};

}  // namespace tendril::physics::ur5
