#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tendril/core/space.hpp"
#include "tendril/physics/contact/cylinder_contact.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::envs::elastica {

// Sizes of the observation building blocks of the Elastica control cases (SPEC M2; seed 000,
// "State Definition" of cases 1–4). All positions and velocities are in the lab frame (m, m/s).
inline constexpr int kRodSamples = 11;             // nodes every n/10 along the arm, ends included
inline constexpr int kRodBlock = 3 * kRodSamples;  // 33
inline constexpr int kVelocityBlock = 4;           // speed, then unit direction
inline constexpr int kPositionBlock = 3;
inline constexpr int kQuaternionBlock = 4;                  // w, x, y, z
inline constexpr int kObstaclePoints = 5;                   // equidistant along an obstacle's axis
inline constexpr int kObstacleBlock = 3 * kObstaclePoints;  // 15

// Appends the building blocks, in the order called, to a float observation of a fixed size.
// Writes in place: no allocation. The caller sizes `out` and checks `written()` at the end;
// values beyond the end are counted but not written.
class ObservationWriter {
 public:
  explicit ObservationWriter(Observation& out) : out_(out) {}

  // kRodBlock values: the kRodSamples sampled nodes coordinate-major, i.e. the x of every
  // sample, then every y, then every z (the row-major flattening of the 3 × 11 matrix
  // Rod::sampled_node_positions(11)).
  void rod_nodes(const physics::Rod& rod);
  // kVelocityBlock values: |v|, then v/|v| (zeros when v = 0, e.g. a stationary target).
  void speed_and_direction(const Eigen::Vector3d& velocity);
  void position(const Eigen::Vector3d& position);
  // kQuaternionBlock values (w, x, y, z) of a unit quaternion.
  void quaternion(const Eigen::Quaterniond& q);
  // kObstacleBlock values: kObstaclePoints points start + (i/4)·length·axis, i = 0 … 4 (both
  // ends of the axis included), coordinate-major like the rod nodes.
  void obstacle(const physics::Cylinder& cylinder);

  int written() const { return next_; }

 private:
  void put(double value) {
    if (next_ < out_.size()) out_[next_] = static_cast<float>(value);
    ++next_;
  }

  Observation& out_;
  int next_ = 0;
};

}  // namespace tendril::envs::elastica
