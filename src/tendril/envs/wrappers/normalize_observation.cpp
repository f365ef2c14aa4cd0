#include "tendril/envs/wrappers/normalize_observation.hpp"

#include <string>

namespace tendril::envs {

namespace {

Space clipped_box(const Space& inner, double clip) {
  require(inner.is_box(), "needs a Box observation space, got " + inner.describe(),
          "envs::NormalizeObservation");
  require(clip > 0.0, "clip must be positive", "envs::NormalizeObservation");
  return Space::box(inner.size(), static_cast<float>(-clip), static_cast<float>(clip));
}

}  // namespace

NormalizeObservation::NormalizeObservation(std::unique_ptr<Env> inner, Options options)
    : Wrapper(std::move(inner)),
      options_(options),
      observation_space_(clipped_box(inner_->observation_space(), options.clip)),
      statistics_(inner_->observation_space().size()) {
  require(options.epsilon > 0.0, "epsilon must be positive", "envs::NormalizeObservation");
}

Observation NormalizeObservation::normalize(const Observation& raw) const {
  return statistics_.normalize(raw.cast<double>(), options_.epsilon, options_.clip).cast<float>();
}

Observation NormalizeObservation::reset(std::optional<uint64_t> seed) {
  const Observation raw = inner_->reset(seed);
  if (training_) statistics_.update(raw.cast<double>());
  return normalize(raw);
}

Step NormalizeObservation::step(const Action& action) {
  Step result = inner_->step(action);
  if (training_) statistics_.update(result.observation.cast<double>());
  result.observation = normalize(result.observation);
  return result;
}

void NormalizeObservation::set_statistics(const RunningMeanStd& statistics) {
  require(statistics.size() == statistics_.size(),
          "statistics have " + std::to_string(statistics.size()) + " components, observations " +
              std::to_string(statistics_.size()),
          "envs::NormalizeObservation");
  statistics_ = statistics;
}

void NormalizeObservation::import_statistics(std::span<const double> values) {
  statistics_ = RunningMeanStd::from_array(values, statistics_.size());
}

}  // namespace tendril::envs
