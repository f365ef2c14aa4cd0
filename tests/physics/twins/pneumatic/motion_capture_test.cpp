#include "tendril/physics/twins/pneumatic/motion_capture.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {
namespace {

TipPositions constant(double value) { return TipPositions::Constant(value); }

TEST(MotionCapture, WithoutNoiseOrLatencyReportsTheTruth) {
  MotionCapture capture(MotionCaptureSpec{}, Rng(1));
  TipPositions truth;
  truth << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  capture.sample(truth);
  EXPECT_EQ(capture.read(), truth);
}

// The centroid of three markers with noise σ per axis has noise σ/√3 per axis: over 20,000
// samples of 9 coordinates the standard deviation comes within 2 % of it (the estimate's own
// relative spread is 1/√(2 · 180,000) ≈ 0.17 %), and the mean within 4 standard errors of 0.
TEST(MotionCapture, TipNoiseIsTheMarkerNoiseOverRootThree) {
  MotionCaptureSpec spec;
  spec.marker_noise = 2e-4;
  MotionCapture capture(spec, Rng(9));
  double sum = 0.0, sum_squares = 0.0;
  const int samples = 20000;
  for (int s = 0; s < samples; ++s) {
    capture.sample(constant(0.0));
    sum += capture.read().sum();
    sum_squares += capture.read().squaredNorm();
  }
  const double n = 9.0 * samples;
  const double sigma = spec.marker_noise / std::sqrt(3.0);
  EXPECT_NEAR(std::sqrt(sum_squares / n), sigma, 0.02 * sigma);
  EXPECT_NEAR(sum / n, 0.0, 4.0 * sigma / std::sqrt(n));
}

// With a latency of 3 sample periods the controller reads the sample taken 3 periods before
// the newest (until there are that many, the oldest held).
TEST(MotionCapture, LatencyDelaysWhatTheControllerReads) {
  MotionCaptureSpec spec;
  spec.latency = 0.03;
  MotionCapture capture(spec, Rng(2));
  capture.restart(constant(0.0));
  capture.sample(constant(1.0));
  EXPECT_EQ(capture.read(), constant(0.0));
  for (int s = 2; s <= 10; ++s) {
    capture.sample(constant(s));
    EXPECT_EQ(capture.read(), constant(std::max(0, s - 3))) << s;
    EXPECT_EQ(capture.newest(), constant(s));
  }
  spec.latency = 0.025;  // not a whole number of samples
  EXPECT_THROW(MotionCapture(spec, Rng(2)), Error);
}

TEST(MotionCapture, SnapshotsRepeatTheNoise) {
  MotionCaptureSpec spec;
  spec.marker_noise = 1e-3;
  spec.latency = 0.02;
  MotionCapture capture(spec, Rng(5));
  for (int s = 0; s < 4; ++s) capture.sample(constant(s));
  Snapshot bytes;
  SnapshotWriter out(bytes);
  capture.save_state(out);
  MotionCapture copy(spec, Rng(77));
  SnapshotReader in(bytes);
  copy.load_state(in);
  for (int s = 0; s < 5; ++s) {
    capture.sample(constant(10.0 + s));
    copy.sample(constant(10.0 + s));
    EXPECT_EQ(copy.read(), capture.read());
  }
}

}  // namespace
}  // namespace tendril::physics::pneumatic
