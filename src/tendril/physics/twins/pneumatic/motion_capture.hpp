#pragma once

#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::physics::pneumatic {

struct MotionCaptureSpec {
  double sample_period = 0.01;  // s; seed 002 §III-A: Vicon at 100 Hz
  // Noise of one marker's position, per axis, m. A module tip is the centroid of 3 markers
  // (§III-A), so its noise is this over √3. [A] 0.2 mm, a typical Vicon figure.
  double marker_noise = 0.0;
  // Age of the sample the controller reads, s, a whole number of sample periods (§III-A:
  // "additional delays were introduced to synchronize the tracking with our control loop", no
  // value).
  double latency = 0.0;

  void validate() const;
  int latency_samples() const;
};

// The motion-capture system: samples the true module-tip positions every `sample_period`,
// adds each sample's noise once (so every reader of a sample sees the same value), and hands
// the controller the newest sample that is at least `latency` old.
class MotionCapture {
 public:
  MotionCapture(const MotionCaptureSpec& spec, Rng rng);

  // Records a sample of the true tip positions (lab frame, m).
  void sample(const TipPositions& truth);
  // Forgets every sample and records `truth` as the only one (start of a trial).
  void restart(const TipPositions& truth);
  // The newest sample at least `latency` old (the oldest one held if there are fewer).
  const TipPositions& read() const;
  const TipPositions& newest() const { return history_[head_]; }
  // Replaces the noise stream (a trial begun with a seed).
  void set_rng(const Rng& rng) { rng_ = rng; }
  const MotionCaptureSpec& spec() const { return spec_; }

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  TipPositions noisy(const TipPositions& truth);

  MotionCaptureSpec spec_;
  Rng rng_;
  std::vector<TipPositions> history_;  // ring of latency_samples + 1 samples
  int head_ = 0;                       // newest
  int count_ = 0;                      // samples held
};

}  // namespace tendril::physics::pneumatic
