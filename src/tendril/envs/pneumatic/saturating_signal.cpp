#include "tendril/envs/pneumatic/saturating_signal.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"

namespace tendril::envs::pneumatic {

using physics::pneumatic::kChambers;

namespace {

std::pair<double, double> range_of(const Config& config, const std::string& key,
                                   std::pair<double, double> fallback) {
  if (!config.has(key)) return fallback;
  const std::vector<double> values = config.get<std::vector<double>>(key);
  if (values.size() != 2) throw Error("needs [min, max]", key_where(config, key));
  return {values[0], values[1]};
}

}  // namespace

SaturatingSignalSpec saturating_signal_from(const Config& config) {
  SaturatingSignalSpec spec;
  spec.ceiling_min = config.get_or<double>("ceiling_min_bar", spec.ceiling_min);
  spec.ceiling_max = config.get_or<double>("ceiling_max_bar", spec.ceiling_max);
  std::tie(spec.ceiling_hold_min, spec.ceiling_hold_max) =
      range_of(config, "ceiling_hold_s", {spec.ceiling_hold_min, spec.ceiling_hold_max});
  std::tie(spec.hold_min, spec.hold_max) =
      range_of(config, "hold_s", {spec.hold_min, spec.hold_max});
  spec.saturation_probability =
      config.get_or<double>("saturation_probability", spec.saturation_probability);
  try {
    spec.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), config.source() + ": " + config.path());
  }
  return spec;
}

void SaturatingSignalSpec::validate() const {
  const char* where = "SaturatingSignalSpec";
  require(std::isfinite(ceiling_min) && std::isfinite(ceiling_max) && ceiling_min >= 0.0 &&
              ceiling_max >= ceiling_min,
          "need 0 <= ceiling_min <= ceiling_max", where);
  require(std::isfinite(ceiling_hold_min) && std::isfinite(ceiling_hold_max) &&
              ceiling_hold_min > 0.0 && ceiling_hold_max >= ceiling_hold_min,
          "need 0 < ceiling_hold_min <= ceiling_hold_max", where);
  require(
      std::isfinite(hold_min) && std::isfinite(hold_max) && hold_min > 0.0 && hold_max >= hold_min,
      "need 0 < hold_min <= hold_max", where);
  require(saturation_probability >= 0.0 && saturation_probability <= 1.0,
          "saturation_probability must lie in [0, 1]", where);
}

SaturatingSignal::SaturatingSignal(const SaturatingSignalSpec& spec, Rng rng)
    : spec_(spec), rng_(rng) {
  spec_.validate();
}

void SaturatingSignal::draw_level(int chamber) {
  const bool saturate = rng_.uniform() < spec_.saturation_probability;
  levels_[chamber] = saturate ? ceiling_ : rng_.uniform(0.0, ceiling_);
  hold_left_[chamber] += rng_.uniform(spec_.hold_min, spec_.hold_max);
}

const physics::pneumatic::ChamberVector& SaturatingSignal::next(double period) {
  if (ceiling_left_ <= 0.0) {
    ceiling_ = rng_.uniform(spec_.ceiling_min, spec_.ceiling_max);
    ceiling_left_ += rng_.uniform(spec_.ceiling_hold_min, spec_.ceiling_hold_max);
    levels_ = levels_.cwiseMin(ceiling_);
  }
  for (int k = 0; k < kChambers; ++k) {
    if (hold_left_[k] <= 0.0) draw_level(k);
  }
  ceiling_left_ -= period;
  hold_left_.array() -= period;
  return levels_;
}

void SaturatingSignal::save_state(SnapshotWriter& out) const {
  out.section("SaturatingSignal");
  out.put(rng_);
  out.put(ceiling_);
  out.put(ceiling_left_);
  out.put_matrix(levels_);
  out.put_matrix(hold_left_);
}

void SaturatingSignal::load_state(SnapshotReader& in) {
  in.section("SaturatingSignal");
  Rng rng = rng_;
  in.get(rng);
  const double ceiling = in.get_double();
  const double ceiling_left = in.get_double();
  physics::pneumatic::ChamberVector levels, hold_left;
  in.get_matrix(levels);
  in.get_matrix(hold_left);
  rng_ = rng;
  ceiling_ = ceiling;
  ceiling_left_ = ceiling_left;
  levels_ = levels;
  hold_left_ = hold_left;
}

}  // namespace tendril::envs::pneumatic
