#include "tendril/physics/twins/sma/bend_sensor.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void BendSensorSpec::validate() const {
  const char* who = "BendSensorSpec";
  require(min_period_ms >= 1 && max_period_ms >= min_period_ms,
          "sample periods must satisfy 1 <= min_period_ms <= max_period_ms", who);
  require(std::isfinite(resolution) && resolution > 0.0, "resolution must be positive", who);
  require(std::isfinite(noise_std) && noise_std >= 0.0, "noise_std must be non-negative", who);
  require(std::isfinite(max_error) && max_error >= 0.5 * resolution,
          "max_error must be at least half the resolution", who);
  require(zero_offset.allFinite(), "zero_offset must be finite", who);
}

BendSensor::BendSensor(const BendSensorSpec& spec, uint64_t seed)
    : spec_((spec.validate(), spec)), rng_(seed) {}

void BendSensor::attach(const RodModel&, const RodState& state) {
  base_frame_ = state.director(0);
  next_sample_ms_ = std::llround(1e3 * state.time);
}

Eigen::Vector2d BendSensor::true_angles_deg(const RodState& state) const {
  const Eigen::Index last = state.directors.cols() - 1;
  const Eigen::Vector3d tip_tangent(state.directors(6, last), state.directors(7, last),
                                    state.directors(8, last));
  const Eigen::Vector3d t = base_frame_ * tip_tangent;  // in the base frame
  const double sideways = std::hypot(t.x(), t.y());
  if (sideways == 0.0) return Eigen::Vector2d::Zero();
  // Bend angle β between the base and tip tangents, in the direction (t_x, t_y) / |(t_x, t_y)|.
  const double bend = std::atan2(sideways, t.z()) * (180.0 / std::numbers::pi);
  return Eigen::Vector2d(t.x(), t.y()) * (bend / sideways);
}

BendReading BendSensor::sample(const RodState& state) {
  BendReading reading;
  reading.time_ms = next_sample_ms_;
  const Eigen::Vector2d truth = true_angles_deg(state) + spec_.zero_offset;
  // The noise stays within max_error − resolution/2, so that after quantisation the reading is
  // within max_error of the truth.
  const double bound = spec_.max_error - 0.5 * spec_.resolution;
  for (int axis = 0; axis < 2; ++axis) {
    double noise = 0.0;
    if (spec_.noise_std > 0.0 && bound > 0.0) {
      do {
        noise = rng_.normal(0.0, spec_.noise_std);
      } while (std::abs(noise) > bound);
    }
    reading.angles_deg[axis] =
        std::round((truth[axis] + noise) / spec_.resolution) * spec_.resolution;
  }
  const int64_t span = spec_.max_period_ms - spec_.min_period_ms + 1;
  next_sample_ms_ += spec_.min_period_ms + static_cast<int64_t>(rng_.below(span));
  return reading;
}

void BendSensor::save_state(SnapshotWriter& out) const {
  out.section("BendSensor");
  out.put(rng_);
  out.put(static_cast<int64_t>(next_sample_ms_));
}

void BendSensor::load_state(SnapshotReader& in) {
  in.section("BendSensor");
  Rng rng = rng_;
  in.get(rng);
  const int64_t next = in.get_int64();
  rng_ = rng;
  next_sample_ms_ = next;
}

}  // namespace tendril::physics
