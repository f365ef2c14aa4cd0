#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tendril/envs/wrappers/running_mean_std.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Observation normalization with Stable-Baselines3 VecNormalize semantics:
//
//   obs' = clip((obs − mean) / sqrt(var + epsilon), −clip, clip),   epsilon 1e-8, clip 10,
//
// where mean and var are running statistics (RunningMeanStd) updated, while training, with
// every observation this wrapper returns — those from reset included — before normalizing it.
// Frozen (set_training(false)) for evaluation, the statistics stay fixed. This wrapper serves
// one environment — typically an evaluation env given a VecEnv's frozen statistics; to train on
// a VecEnv, attach a VecNormalize (vector/vec_normalize.hpp), which keeps one set of statistics
// for all its environments as SB3 does.
class NormalizeObservation : public Wrapper {
 public:
  struct Options {
    double clip = 10.0;
    double epsilon = 1e-8;
  };

  // The inner observation space must be a Box.
  explicit NormalizeObservation(std::unique_ptr<Env> inner)
      : NormalizeObservation(std::move(inner), Options{}) {}
  NormalizeObservation(std::unique_ptr<Env> inner, Options options);

  const Space& observation_space() const override { return observation_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  // The normalized form of a raw observation under the current statistics.
  Observation normalize(const Observation& raw) const;

  bool training() const { return training_; }
  void set_training(bool training) { training_ = training; }

  const RunningMeanStd& statistics() const { return statistics_; }
  // Raises Error if `statistics` has a different size than the observations.
  void set_statistics(const RunningMeanStd& statistics);
  // The statistics as plain numbers (RunningMeanStd::to_array layout) and back, exactly.
  std::vector<double> export_statistics() const { return statistics_.to_array(); }
  void import_statistics(std::span<const double> values);

 private:
  Options options_;
  Space observation_space_;
  RunningMeanStd statistics_;
  bool training_ = true;
};

}  // namespace tendril::envs
