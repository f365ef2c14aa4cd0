#pragma once

#include <array>

#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::envs::pneumatic {

// The "dynamically saturating pressure signal" of seed 002 §III-C: "the pressure ceiling was
// varied dynamically, while respecting the safety threshold, and saturated at that pressure for
// randomly chosen time instants for all nine pressure signals". The seed gives no numbers; this
// reading ([A], the spec's suggestion with a saturation probability added):
// - one ceiling for all nine signals, redrawn uniformly in [ceiling_min, ceiling_max] bar at
//   intervals drawn uniformly in [ceiling_hold_min, ceiling_hold_max] s;
// - each signal holds a level for a time drawn uniformly in [hold_min, hold_max] s, then draws
//   the next: with probability `saturation_probability` the current ceiling (it saturates),
//   otherwise uniform in [0, ceiling];
// - a level above a newly lowered ceiling is cut to it at once (the ceiling is never exceeded).
struct SaturatingSignalSpec {
  double ceiling_min = 0.5;       // bar
  double ceiling_max = 1.5;       // bar, at most the safety ceiling
  double ceiling_hold_min = 5.0;  // s
  double ceiling_hold_max = 20.0;
  double hold_min = 0.5;  // s
  double hold_max = 3.0;
  double saturation_probability = 0.3;

  void validate() const;
};

// The spec from an experiment's `signal` mapping (all optional): ceiling_min_bar,
// ceiling_max_bar, ceiling_hold_s: [min, max], hold_s: [min, max], saturation_probability.
// Raises Error naming the mapping for inconsistent values.
SaturatingSignalSpec saturating_signal_from(const Config& config);

class SaturatingSignal {
 public:
  SaturatingSignal(const SaturatingSignalSpec& spec, Rng rng);

  // The nine commands (bar) to hold over the next `period` seconds; the signal's clock then
  // advances by `period`.
  const physics::pneumatic::ChamberVector& next(double period);
  double ceiling() const { return ceiling_; }

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  void draw_level(int chamber);

  SaturatingSignalSpec spec_;
  Rng rng_;
  double ceiling_ = 0.0;
  double ceiling_left_ = 0.0;  // s until the ceiling is redrawn
  physics::pneumatic::ChamberVector levels_ = physics::pneumatic::ChamberVector::Zero();
  physics::pneumatic::ChamberVector hold_left_ = physics::pneumatic::ChamberVector::Zero();
};

}  // namespace tendril::envs::pneumatic
