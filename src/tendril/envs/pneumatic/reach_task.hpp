#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>

namespace tendril::envs::pneumatic {

// The reaching task of seed 002 §IV-A (eq. (2)): module 3's tip must come within 5 mm of a goal
// behind a plate without touching the plate, inside a boundary box. Robot frame, mm.
//
// How the seed is read where it leaves room (docs/results/pneumatic_arm.md lists these):
// - the reward's cases are added, not exclusive, and the −2 step penalty applies every step;
// - the obstacle is the 5 mm thick cuboid plate, and O_dist the distance from the tip to it
//   (0 inside). The seed's formula n·V/|n| is the distance to the plate's infinite plane, under
//   which no path around the plate exists (the plate spans B's whole height); kPlane keeps it;
// - a collision is (a) the segment from the previous to the current tip crossing the plate or
//   (b) O_dist ≤ 10 mm; it ends the episode;
// - leaving B ends the episode (its −100 is the last reward); reaching the goal ends it too.
struct ReachTaskSpec {
  enum class ObstacleDistance { kBox, kPlane };

  Eigen::Vector3d goal{-30.0, -120.0, -620.0};
  Eigen::AlignedBox3d obstacle{Eigen::Vector3d(-60.0, -55.0, -700.0),
                               Eigen::Vector3d(60.0, -50.0, -570.0)};
  Eigen::AlignedBox3d boundary{Eigen::Vector3d(-130.0, -150.0, -700.0),
                               Eigen::Vector3d(90.0, 50.0, -570.0)};
  double success_distance = 5.0;   // G_dist at which the goal counts as reached
  double warning_distance = 20.0;  // O_dist band (collision, warning] costs −5 (20 − O_dist)
  double collision_distance = 10.0;
  double warning_gain = 5.0;
  double step_penalty = -2.0;
  double boundary_penalty = -100.0;
  double collision_penalty = -10000.0;
  bool terminate_outside_boundary = true;
  ObstacleDistance obstacle_distance = ObstacleDistance::kBox;

  // The task settings of the paper, by name:
  //   main  goal [−30, −120, −620], plate z ∈ [−700, −570] (Figs. 9–10; Sec. V-C1)
  //   G1    goal [50, −100, −620],  plate z ∈ [−700, −610] (Table II)
  //   G2    goal [−50, −100, −625], plate z ∈ [−700, −610]
  //   G3    goal [−45, −100, −645], plate z ∈ [−700, −570]
  // all with the plate x ∈ [−60, 60], y ∈ [−55, −50] and B x ∈ [−130, 90], y ∈ [−150, 50],
  // z ∈ [−700, −570] (Sec. III-A). Raises tendril::Error naming `where` for another name.
  static ReachTaskSpec preset(std::string_view name, std::string_view where = {});
  // GPRCA's relaxed boundary (Sec. V-C2): x ∈ [−170, 80], y ∈ [−170, 50], z ∈ [−700, −570].
  static Eigen::AlignedBox3d relaxed_boundary();

  // Raises tendril::Error naming the first inconsistent field.
  void validate() const;
};

// What one step of the task scores (eq. (2) and its flags).
struct ReachOutcome {
  double reward = 0.0;
  double goal_distance = 0.0;      // G_dist, mm
  double obstacle_distance = 0.0;  // O_dist, mm
  bool success = false;            // G_dist ≤ success_distance and no collision
  bool collision = false;
  bool warning = false;       // collision_distance < O_dist ≤ warning_distance
  bool outside = false;       // tip ∉ B
  bool ends_episode = false;  // success, collision, or outside B when that terminates
};

// O_dist of `point` (mm) under the spec's distance rule: kBox, the Euclidean distance to the
// plate (0 inside); kPlane, the distance to the plate's mid-plane (normal along its thinnest
// side) less half its thickness, at least 0.
double obstacle_distance(const ReachTaskSpec& spec, const Eigen::Vector3d& point);

// Whether the segment from `from` to `to` meets the closed box (slab test).
bool segment_meets_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& from,
                       const Eigen::Vector3d& to);

// Scores the step in which module 3's tip moved from `previous_tip` to `tip` (mm):
//   −2                        every step
//   −100                      tip ∉ B
//   −5 (20 − O_dist)          10 < O_dist ≤ 20
//   −10000                    collision: segment crosses the plate, or O_dist ≤ 10
//   −G_dist                   G_dist > 5
ReachOutcome evaluate_reach_step(const ReachTaskSpec& spec, const Eigen::Vector3d& previous_tip,
                                 const Eigen::Vector3d& tip);

}  // namespace tendril::envs::pneumatic
