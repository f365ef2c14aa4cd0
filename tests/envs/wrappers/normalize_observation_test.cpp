#include "tendril/envs/wrappers/normalize_observation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/cart_pole.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

const Action kAction = Eigen::Vector2f(0.0f, 0.5f);

// ScriptedEnv observes [steps, resets, seed]: after reset(4) and two steps the samples are
// [0,1,4], [1,1,4], [2,1,4]. Pooled with SB3's prior (count 1e-4, mean 0, var 1):
TEST(NormalizeObservation, MatchesHandComputedRunningStatistics) {
  NormalizeObservation env(std::make_unique<ScriptedEnv>());
  env.reset(4);
  env.step(kAction);
  const Observation third = env.step(kAction).observation;

  const double n = 3.0 + 1e-4;
  const double mean_steps = (0.0 + 1.0 + 2.0) / n;
  const double var_steps = (1e-4 * (1.0 + mean_steps * mean_steps) + std::pow(0.0 - mean_steps, 2) +
                            std::pow(1.0 - mean_steps, 2) + std::pow(2.0 - mean_steps, 2)) /
                           n;
  const double mean_resets = 3.0 / n;
  const double var_resets =
      (1e-4 * (1.0 + mean_resets * mean_resets) + 3.0 * std::pow(1.0 - mean_resets, 2)) / n;

  EXPECT_NEAR(env.statistics().count(), n, 1e-12);
  EXPECT_NEAR(env.statistics().mean()[0], mean_steps, 1e-12);
  EXPECT_NEAR(env.statistics().var()[0], var_steps, 1e-12);
  EXPECT_NEAR(env.statistics().var()[1], var_resets, 1e-12);
  EXPECT_NEAR(third[0], (2.0 - mean_steps) / std::sqrt(var_steps + 1e-8), 1e-6);
  EXPECT_NEAR(third[1], (1.0 - mean_resets) / std::sqrt(var_resets + 1e-8), 1e-4);
}

TEST(NormalizeObservation, ClipsAtTenAndFreezesForEvaluation) {
  NormalizeObservation env(std::make_unique<ScriptedEnv>());
  RunningMeanStd stats(3);
  stats.update_from_moments(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.01, 0.01, 0.01),
                            10.0);
  env.set_statistics(stats);
  env.set_training(false);
  const Observation obs = env.reset(4);  // raw [0, 1, 4]
  const double std_dev = std::sqrt(env.statistics().var()[1] + 1e-8);
  EXPECT_FLOAT_EQ(obs[1], static_cast<float>((1.0 - env.statistics().mean()[1]) / std_dev));
  EXPECT_FLOAT_EQ(obs[2], 10.0f);  // 4 / 0.1 = 40, clipped
  for (int t = 0; t < 5; ++t) env.step(kAction);
  EXPECT_EQ(env.statistics(), stats);  // frozen: nothing was folded in
  EXPECT_EQ(env.observation_space().describe(), "Box(3, [-10, 10])");
}

TEST(NormalizeObservation, StatisticsExportImportRoundTripsExactly) {
  NormalizeObservation trained(std::make_unique<Pendulum>());
  trained.reset(1);
  for (int t = 0; t < 37; ++t) trained.step(Action::Constant(1, 0.3f * (t % 5) - 0.6f));
  const std::vector<double> saved = trained.export_statistics();

  NormalizeObservation restored(std::make_unique<Pendulum>());
  restored.import_statistics(saved);
  EXPECT_EQ(restored.export_statistics(), saved);
  EXPECT_EQ(restored.statistics(), trained.statistics());
  const Observation raw = Eigen::Vector3f(0.3f, -0.9f, 2.5f);
  EXPECT_EQ(restored.normalize(raw), trained.normalize(raw));

  EXPECT_THROW(restored.import_statistics(std::vector<double>(5, 1.0)), Error);
  EXPECT_THROW(
      NormalizeObservation(std::make_unique<ScriptedEnv>()).set_statistics(RunningMeanStd(2)),
      Error);
}

TEST(NormalizeObservation, RequiresABoxObservationSpace) {
  class DiscreteObservations : public CartPole {
   public:
    const Space& observation_space() const override { return space_; }

   private:
    Space space_ = Space::discrete(4);
  };
  EXPECT_THROW(NormalizeObservation(std::make_unique<DiscreteObservations>()), Error);
}

}  // namespace
}  // namespace tendril::envs
