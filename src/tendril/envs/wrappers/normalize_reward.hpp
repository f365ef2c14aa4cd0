#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tendril/envs/wrappers/running_mean_std.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Reward scaling with Stable-Baselines3 VecNormalize semantics: a discounted return
// R ← γR + r is accumulated along the episode, its running variance tracked (RunningMeanStd,
// updated with every R while training), and each reward divided by its standard deviation:
//
//   r' = clip(r / sqrt(var(R) + epsilon), −clip, clip),   γ 0.99, epsilon 1e-8, clip 10.
//
// R restarts at 0 after a terminated or truncated step and on reset. The reward is scaled, not
// centred, so the sign of every reward is kept. Frozen (set_training(false)) for evaluation, the
// statistics stay fixed. Put EpisodeStatistics inside this wrapper to report raw returns. This
// wrapper serves one environment; on a VecEnv, VecNormalize (vector/vec_normalize.hpp) keeps
// one return statistic for all its environments as SB3 does.
class NormalizeReward : public Wrapper {
 public:
  struct Options {
    double gamma = 0.99;
    double clip = 10.0;
    double epsilon = 1e-8;
  };

  explicit NormalizeReward(std::unique_ptr<Env> inner)
      : NormalizeReward(std::move(inner), Options{}) {}
  NormalizeReward(std::unique_ptr<Env> inner, Options options);

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  // The scaled form of a raw reward under the current statistics.
  double normalize(double raw) const;

  bool training() const { return training_; }
  void set_training(bool training) { training_ = training; }

  // Statistics of the discounted return (one component).
  const RunningMeanStd& statistics() const { return statistics_; }
  void set_statistics(const RunningMeanStd& statistics);
  std::vector<double> export_statistics() const { return statistics_.to_array(); }
  void import_statistics(std::span<const double> values);

  double discounted_return() const { return discounted_return_; }

 private:
  Options options_;
  RunningMeanStd statistics_{1};
  double discounted_return_ = 0.0;
  bool training_ = true;
};

}  // namespace tendril::envs
