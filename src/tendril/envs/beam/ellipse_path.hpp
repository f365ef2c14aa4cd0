#pragma once

#include <vector>

#include "tendril/envs/beam/target_path.hpp"

namespace tendril::envs::beam {

// Seed 003's ellipse (Sec. VII, with b = a √(1 − e²) and θ = ω t):
//   x = a sin θ,                 v_x = a ω cos θ,
//   y = top − b (1 − cos θ),     v_y = −b ω sin θ.
// The seed writes y = b (1 − cos θ) about the ellipse's own origin; here that origin (the θ = 0
// point) sits on the beam's axis at y = `top`, just below the straight beam's tip, and the
// ellipse extends towards the base, so it starts where the tip is. a, e, ω are drawn per episode
// from the level's ranges. The default levels are a curriculum from fixed values to the seed's
// ranges (Fig. 18): L0 a = 0.2 m, e = 0.6, ω = 0.5 rad/s; L1 those ± a quarter of each range's
// width (clipped to it); L2 a ∈ [0.18, 0.25] m, e ∈ [0.5, 0.8], ω ∈ [0.5, 1.0] rad/s.
struct EllipseLevel {
  Range semi_major_axis{0.18, 0.25};  // m
  Range eccentricity{0.5, 0.8};
  Range angular_velocity{0.5, 1.0};  // rad/s
};

struct EllipseSpec {
  std::vector<EllipseLevel> levels = default_levels(EllipseLevel{});
  double top = 0.70;  // m
  // L0 fixed at a = 0.2 m, e = 0.6, ω = 0.5 rad/s; L1 those ± a quarter of each of `full`'s
  // widths, clipped to `full`; L2 `full`.
  static std::vector<EllipseLevel> default_levels(const EllipseLevel& full);
  // Raises Error naming the field.
  void validate() const;
};

class EllipsePath final : public TargetPath {
 public:
  explicit EllipsePath(EllipseSpec spec);

  void reset(Rng& rng) override;
  void advance(Rng& rng, double dt) override;
  Eigen::Vector2d position() const override;
  Eigen::Vector2d velocity() const override;
  int levels() const override { return static_cast<int>(spec_.levels.size()); }
  Eigen::Matrix2Xd polyline(int points) const override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  double semi_major_axis() const { return semi_major_axis_; }
  double semi_minor_axis() const;
  double angular_velocity() const { return angular_velocity_; }
  double phase() const { return phase_; }  // θ, rad

 private:
  EllipseSpec spec_;
  double semi_major_axis_ = 0.2, eccentricity_ = 0.6, angular_velocity_ = 0.5, phase_ = 0.0;
};

}  // namespace tendril::envs::beam
