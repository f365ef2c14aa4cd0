#pragma once

#include <Eigen/Core>
#include <string>

#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"

namespace tendril::envs::beam {

// A closed interval a task draws a parameter from, uniformly, once per episode; low == high
// fixes it.
struct Range {
  double low = 0.0, high = 0.0;
  double sample(Rng& rng) const { return rng.uniform(low, high); }
  // Raises Error naming `what` unless low ≤ high, both finite and within [min, max].
  void validate(const std::string& what, double min, double max) const;
};

// How a beam task's target moves in the plane of the beam (lab frame, m; the beam's base at the
// origin, pointing along +y), with levels of difficulty for a curriculum (envs::Curriculum).
class TargetPath {
 public:
  virtual ~TargetPath() = default;

  // Draws the episode's parameters at the current level and places the target at its start.
  virtual void reset(Rng& rng) = 0;
  // Moves the target on by `dt` seconds.
  virtual void advance(Rng& rng, double dt) = 0;
  virtual Eigen::Vector2d position() const = 0;  // m
  virtual Eigen::Vector2d velocity() const = 0;  // m/s

  virtual int levels() const = 0;
  int level() const { return level_; }
  // Takes effect at the next reset; raises Error outside [0, levels()).
  void set_level(int level);

  // The whole path of this episode as a polyline of `points` points, for viewers.
  virtual Eigen::Matrix2Xd polyline(int points) const = 0;

  // The episode's parameters and the target's phase; load_state reads everything before it
  // changes anything.
  virtual void save_state(SnapshotWriter& out) const = 0;
  virtual void load_state(SnapshotReader& in) = 0;

 protected:
  int level_ = 0;
};

}  // namespace tendril::envs::beam
