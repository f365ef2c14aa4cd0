#include "tendril/physics/twins/pneumatic/motion_capture.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {

void MotionCaptureSpec::validate() const {
  const char* where = "MotionCaptureSpec";
  require(std::isfinite(sample_period) && sample_period > 0.0,
          "sample_period must be finite and positive", where);
  require(std::isfinite(marker_noise) && marker_noise >= 0.0,
          "marker_noise must be finite and non-negative", where);
  require(std::isfinite(latency) && latency >= 0.0 && latency <= 1.0,
          "latency must lie in [0, 1] s", where);
  const double periods = latency / sample_period;
  if (std::abs(periods - std::round(periods)) > 1e-6) {
    throw Error("latency (" + std::to_string(latency) +
                    " s) must be a whole number of sample periods (" +
                    std::to_string(sample_period) + " s)",
                where);
  }
}

int MotionCaptureSpec::latency_samples() const {
  return static_cast<int>(std::lround(latency / sample_period));
}

MotionCapture::MotionCapture(const MotionCaptureSpec& spec, Rng rng) : spec_(spec), rng_(rng) {
  spec_.validate();
  history_.assign(spec_.latency_samples() + 1, TipPositions::Zero());
}

TipPositions MotionCapture::noisy(const TipPositions& truth) {
  if (spec_.marker_noise == 0.0) return truth;
  // The centroid of three markers with independent noise σ per axis has noise σ/√3 per axis.
  const double sigma = spec_.marker_noise / std::sqrt(3.0);
  TipPositions sample = truth;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) sample(r, c) += sigma * rng_.normal();
  }
  return sample;
}

void MotionCapture::sample(const TipPositions& truth) {
  head_ = (head_ + 1) % static_cast<int>(history_.size());
  history_[head_] = noisy(truth);
  if (count_ < static_cast<int>(history_.size())) ++count_;
}

void MotionCapture::restart(const TipPositions& truth) {
  head_ = 0;
  count_ = 1;
  history_[0] = noisy(truth);
}

const TipPositions& MotionCapture::read() const {
  const int size = static_cast<int>(history_.size());
  const int age = std::min(spec_.latency_samples(), count_ - 1);
  return history_[(head_ - age + size) % size];
}

void MotionCapture::save_state(SnapshotWriter& out) const {
  out.section("MotionCapture");
  out.put(rng_);
  out.put(static_cast<int64_t>(history_.size()));
  for (const TipPositions& sample : history_) out.put_matrix(sample);
  out.put(static_cast<int64_t>(head_));
  out.put(static_cast<int64_t>(count_));
}

void MotionCapture::load_state(SnapshotReader& in) {
  in.section("MotionCapture");
  Rng rng = rng_;
  in.get(rng);
  const int64_t size = in.get_int64();
  if (size != static_cast<int64_t>(history_.size())) {
    throw Error("snapshot holds " + std::to_string(size) + " samples, this sensor " +
                    std::to_string(history_.size()),
                "MotionCapture::load_state");
  }
  std::vector<TipPositions> history = history_;
  for (TipPositions& sample : history) in.get_matrix(sample);
  const int64_t head = in.get_int64();
  const int64_t count = in.get_int64();
  if (head < 0 || head >= size || count < 1 || count > size) {
    throw Error("snapshot holds an invalid sample ring", "MotionCapture::load_state");
  }
  rng_ = rng;
  history_ = std::move(history);
  head_ = static_cast<int>(head);
  count_ = static_cast<int>(count);
}

}  // namespace tendril::physics::pneumatic
