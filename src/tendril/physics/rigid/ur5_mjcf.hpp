#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

#include "tendril/physics/rigid/ur5_parameters.hpp"

namespace tendril::physics {

// The UR5 on a table with one obstacle box, written as MJCF from the published parameters
// (ur5_parameters.hpp); no mesh or other asset is read.
//
// Frames: the lab frame is the robot's base frame (DH frame 0), z up, the table top at z = 0.
// Body k (k = 1…6) is DH frame k−1 turned by joint k about its z axis; body k+1 sits at
// (a_k, 0, d_k) in body k, turned by α_k about x, so the model's flange site ("flange") is DH
// frame 6 exactly (tests/physics/rigid/ur5_model_test.cpp checks it against the DH formulas).
//
// Bodies and geoms (capsules of the real links' size, where the real links are):
//   shoulder_link   base column 0 → d₁ (r 0.06 m) and the shoulder housing along joint 2
//   upper_arm_link  0.425 m tube 0.13585 m out along the shoulder axis (r 0.05) and the elbow
//   forearm_link    0.39225 m tube 0.01615 m out (r 0.04)
//   wrist_1_link    wrist 1 → wrist 2 offset d₄ (r 0.04)
//   wrist_2_link    wrist 2 → wrist 3 offset d₅ (r 0.04)
//   wrist_3_link    the tool flange, its end cap at the flange (r 0.035)
// and in the world: the table (plane z = 0, "table") and the obstacle ("obstacle", a box).
// Masses and centres of mass are the published ones; each link's inertia is that of a solid
// cylinder of its geometry's size (the published tables give none). The base column rests on
// the table, so contacts between the world and shoulder_link are excluded; MuJoCo already
// ignores contacts between a body and its parent.
//
// Actuation: one MuJoCo position servo per joint, torque = kp·(q_target − q) saturated at the
// UR5's joint torques, with viscous joint damping and rotor inertia (armature). Semi-implicit
// Euler integration (MuJoCo's default, implicit in the joint damping).
struct Ur5SceneSpec {
  double timestep = 0.002;                                                         // s
  std::array<double, ur5::kJoints> stiffness = {2000, 2000, 2000, 300, 300, 300};  // N·m/rad
  std::array<double, ur5::kJoints> damping = {100, 100, 100, 15, 15, 15};          // N·m·s/rad
  std::array<double, ur5::kJoints> armature = {0.1, 0.1, 0.1, 0.02, 0.02, 0.02};   // kg·m²
  Eigen::Vector3d obstacle_centre{0.40, 0.0, 0.10};                                // m, lab frame
  Eigen::Vector3d obstacle_half_extents{0.05, 0.20, 0.10};  // m, axis-aligned

  // Raises Error naming the first non-finite or non-positive value.
  void validate() const;
};

// Names the model uses for the elements a controller or a viewer needs.
namespace ur5_names {
inline constexpr const char* kFlangeSite = "flange";
inline constexpr const char* kTableGeom = "table";
inline constexpr const char* kObstacleGeom = "obstacle";
inline constexpr std::array<const char*, ur5::kJoints> kLinkBodies = {
    "shoulder_link", "upper_arm_link", "forearm_link",
    "wrist_1_link",  "wrist_2_link",   "wrist_3_link"};
}  // namespace ur5_names

// The MJCF document of the scene.
std::string ur5_mjcf(const Ur5SceneSpec& spec);

}  // namespace tendril::physics
