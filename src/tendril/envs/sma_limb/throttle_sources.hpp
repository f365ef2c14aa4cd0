#pragma once

#include <Eigen/Core>

#include "tendril/core/rng.hpp"
#include "tendril/envs/sma_limb/visit_grid.hpp"

namespace tendril::envs::sma_limb {

// What drives the limb during data collection: every reading is shown to observe(); next()
// chooses the integer throttles (u_x, u_y) for the coming hold.
class ThrottleSource {
 public:
  virtual ~ThrottleSource() = default;
  virtual void observe(const Eigen::Vector2d& /*angles_deg*/) {}
  virtual Eigen::Vector2i next(const Eigen::Vector2d& angles_deg, Rng& rng) = 0;
};

// Count-based exploration, Algorithm 1 of the thesis (seed 001, §4.2.2):
//   observe:    g[c] ← g[c] + 1 for the state's cell c; m ← max(m, g[c])          (lines 4–9)
//   SampleCell: a target cell with probability ∝ m + 1 − g[c]                      (lines 14–23)
//   ComputeAction: per axis, throttles that take the state towards the target      (lines 24–33)
// with one of two ComputeAction rules, both with the sign towards the target:
//   kUniform (the thesis' listing): per axis a throttle magnitude drawn from 1 … 10;
//   kRandomWalk (the author's exploration firmware, spec §2.2 and suggestion 6; the default):
//     per axis the throttle steps by a random 0 … 3 levels towards the target's column / row
//     (clipped to ±10), or by 0 … 3 back towards zero when the state is already in it; within
//     20° of the target's centre the direction is one of the 8 neighbouring cells at random.
// The thesis' listing gives the opposite sign (a negative throttle when the state is below the
// target); with this limb's convention — a positive throttle bends towards positive angles —
// only this sign moves the state towards the target, which is the algorithm's intent (spec
// §2.2). The slow thermal actuator averages successive holds, so drawing a fresh magnitude each
// hold mostly cancels out; the random walk keeps a direction long enough to travel (see
// docs/results/sma_limb.md for both against babbling).
class CountBasedExploration final : public ThrottleSource {
 public:
  enum class Rule { kRandomWalk, kUniform };
  static constexpr int kMaxStep = 3;
  static constexpr double kArrivedDeg = 20.0;

  explicit CountBasedExploration(Rule rule = Rule::kRandomWalk, VisitGrid grid = VisitGrid());

  void observe(const Eigen::Vector2d& angles_deg) override { grid_.visit(angles_deg); }
  Eigen::Vector2i next(const Eigen::Vector2d& angles_deg, Rng& rng) override;

  int sample_cell(Rng& rng) const;
  Eigen::Vector2i uniform_action(const Eigen::Vector2d& angles_deg, int target, Rng& rng) const;
  Eigen::Vector2i walk_action(const Eigen::Vector2d& angles_deg, int target, Rng& rng);
  const VisitGrid& grid() const { return grid_; }
  const Eigen::Vector2i& throttles() const { return throttles_; }

 private:
  Rule rule_;
  VisitGrid grid_;
  Eigen::Vector2i throttles_ = Eigen::Vector2i::Zero();  // the random walk's state
};

// Naive random motor babbling, the baseline of the thesis' Fig. 4.2 (after its ref. [10]), as
// the author's babbling firmware drew it (spec §2.2): each hold, one coil or two neighbouring
// coils (equally likely); the coil at random among the four, the neighbour at random among the
// two on the other axis; each driven at a level drawn uniformly from 0 … 10 — whatever the
// state.
class MotorBabbling final : public ThrottleSource {
 public:
  Eigen::Vector2i next(const Eigen::Vector2d& angles_deg, Rng& rng) override;
};

}  // namespace tendril::envs::sma_limb
