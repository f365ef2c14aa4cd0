#pragma once

#include <vector>

#include "tendril/envs/beam/target_path.hpp"

namespace tendril::envs::beam {

// Seed 003's arcs (Sec. IV–V): the target runs along an arc of radius r about the beam's base,
// symmetric about the beam's axis, `arc_angle` wide (160°), at angular speed ω, starting at a
// random angle in a random direction. Its direction flips at random (a Poisson process of mean
// interval `mean_reversal_interval` s — the seed's "the direction of the target can change
// suddenly", which it found to help) and at the arc's ends, where it reflects. Angle φ is
// measured from +y towards +x: position r (sin φ, cos φ), velocity s ω r (cos φ, −sin φ) with
// s = ±1. r and ω are drawn per episode from the level's ranges.
struct ArcLevel {
  Range radius{0.2, 0.6};            // m
  Range angular_velocity{0.5, 0.5};  // rad/s
};

struct ArcSpec {
  std::vector<ArcLevel> levels{ArcLevel{}};
  double arc_angle = 160.0;             // degrees
  double mean_reversal_interval = 3.0;  // s; 0: only at the ends
  // Raises Error naming the field.
  void validate() const;
};

class ArcPath final : public TargetPath {
 public:
  explicit ArcPath(ArcSpec spec);

  void reset(Rng& rng) override;
  void advance(Rng& rng, double dt) override;
  Eigen::Vector2d position() const override;
  Eigen::Vector2d velocity() const override;
  int levels() const override { return static_cast<int>(spec_.levels.size()); }
  Eigen::Matrix2Xd polyline(int points) const override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  double radius() const { return radius_; }
  double angular_velocity() const { return angular_velocity_; }
  double angle() const { return angle_; }          // rad, from +y towards +x
  double direction() const { return direction_; }  // +1 or −1
  // Test hook: places the target.
  void set_state(double radius, double angular_velocity, double angle, double direction);

 private:
  ArcSpec spec_;
  double half_angle_;  // rad
  double radius_ = 0.4, angular_velocity_ = 0.5, angle_ = 0.0, direction_ = 1.0;
};

}  // namespace tendril::envs::beam
