#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "tendril/core/rng.hpp"
#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// The thesis' two-axis capacitive bend sensor (Bend Labs; seed 001, Ch. 3, §4.4): it reports the
// bending angle of the limb's end about two axes, read by the Arduino between actuation updates.
// - The angles: the tip's tangent t = d3 seen in the base frame (x = d1, y = d2, z = d3 of the
//   clamped element) is bent from the base axis by β = atan2(|(t_x, t_y)|, t_z) towards the
//   direction (t_x, t_y); the two axes read that bend's components, (θx, θy) = β (t_x, t_y) /
//   |(t_x, t_y)|, in degrees. A limb bent in the x–z plane reads θx = β, θy = 0, up to 180°; a
//   limb bent towards +x reads θx > 0.
// - Timing: a reading every 55–75 ms (uniform, whole milliseconds of the Arduino's clock; the
//   thesis quotes 50–55 ms and 13 Hz, its data sets imply ≈ 71–75 ms, the author's recordings
//   18 Hz; spec §1.1).
// - Errors: Gaussian noise of σ = 0.2° kept within the sensor's 0.5° maximum error (§4.4), then
//   quantised to its 0.1° resolution, plus a per-limb zero offset (the calibration sketch
//   subtracted −10° and −12°).
struct BendSensorSpec {
  int min_period_ms = 55;
  int max_period_ms = 75;
  double noise_std = 0.2;   // deg
  double max_error = 0.5;   // deg, |reading − (true angle + offset)| never exceeds it
  double resolution = 0.1;  // deg
  Eigen::Vector2d zero_offset = Eigen::Vector2d::Zero();  // deg, added to the true angles

  void validate() const;
};

struct BendReading {
  int64_t time_ms = 0;  // the Arduino's clock since the limb was built
  Eigen::Vector2d angles_deg = Eigen::Vector2d::Zero();                // θx, θy as reported
  double time() const { return 1e-3 * static_cast<double>(time_ms); }  // s
};

// A rod part only for its state (the sampling clock and the noise stream), which snapshots keep;
// it adds no loads. The owner advances the rod to next_sample_time() and calls sample().
class BendSensor final : public RodPart {
 public:
  BendSensor(const BendSensorSpec& spec, uint64_t seed);

  uint32_t stages() const override { return 0; }
  void attach(const RodModel& model, const RodState& state) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  const BendSensorSpec& spec() const { return spec_; }
  int64_t next_sample_ms() const { return next_sample_ms_; }
  // The reading due now (the rod at next_sample_ms()); draws the time of the next one.
  BendReading sample(const RodState& state);
  // The true angles (deg) of `state`, without offset, noise or quantisation.
  Eigen::Vector2d true_angles_deg(const RodState& state) const;

 private:
  BendSensorSpec spec_;
  Rng rng_;
  Eigen::Matrix3d base_frame_ = Eigen::Matrix3d::Identity();  // rows x, y, z (lab), at attach
  int64_t next_sample_ms_ = 0;
};

}  // namespace tendril::physics
