#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <vector>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/rigid/mujoco_sim.hpp"
#include "tendril/physics/rigid/ur5_mjcf.hpp"

namespace tendril::physics {

// The UR5 in its scene (ur5_mjcf.hpp), simulated by MuJoCo under position control.
//
// Control: set_targets gives each joint's position servo a target (clipped to the joint's
// limits). During each physics step the controller also cancels the arm's bias forces — gravity
// and the velocity-product (Coriolis, centrifugal) terms MuJoCo computes as qfrc_bias — as the
// UR5's own controller compensates gravity; a joint then behaves like a damped spring towards
// its target and holds still when the target is its current angle.
//
// Collisions: contacts MuJoCo reports between a link and anything but its parent (the table,
// the obstacle, another link) are collisions; advance counts them at every physics step and in
// the final state.
//
// State and snapshots: everything that evolves is MuJoCo's state (MujocoSim), the targets
// included (they are the actuators' controls).
class Ur5Arm {
 public:
  using Joints = Eigen::Matrix<double, ur5::kJoints, 1>;

  struct Advance {
    bool stable = true;  // false if MuJoCo found a non-finite or huge state and reset it
    int contacts = 0;    // the most arm contacts seen at any physics step of the advance
  };

  // The generated scene of `spec`; or, when `model_file` is given, an MJCF file with the same
  // element names (ur5_names, kJointNames; spec then only validates). Raises Error on a model
  // MuJoCo rejects or that lacks a named element.
  explicit Ur5Arm(const Ur5SceneSpec& spec = {}, const std::filesystem::path& model_file = {});

  static Joints lower_limits();
  static Joints upper_limits();

  // Puts the arm at rest at `q` (rad, within the limits, or Error), targets = q, time 0.
  void place(const Joints& q);
  // Servo targets, clipped to the joint limits; returns them as set.
  const Joints& set_targets(const Joints& targets);
  const Joints& targets() const { return targets_; }
  // Runs `steps` physics steps (of spec.timestep each).
  Advance advance(int steps);

  Joints joint_positions() const;           // rad
  Joints joint_velocities() const;          // rad/s
  Eigen::Vector3d flange_position() const;  // m, lab frame
  Eigen::Matrix3d flange_rotation() const;  // flange → lab; its z column is the tool axis
  int contacts() const;                     // arm contacts in the current state
  double time() const;                      // s since place()
  double timestep() const;                  // s

  // The obstacle box as compiled (lab frame, m).
  Eigen::Vector3d obstacle_centre() const;
  Eigen::Vector3d obstacle_half_extents() const;

  // Links as capsules (role "arm"), the obstacle (role "obstacle") and the table (role "table").
  void describe(Scene& scene) const;

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

  const MujocoSim& sim() const { return sim_; }

 private:
  int count_contacts() const;
  void read_targets();

  MujocoSim sim_;
  std::array<int, ur5::kJoints> qpos_address_{}, dof_address_{}, actuator_{};
  std::vector<char> is_link_body_;  // by MuJoCo body id
  int flange_site_ = -1;
  int obstacle_geom_ = -1;
  Joints targets_ = Joints::Zero();
};

}  // namespace tendril::physics
