// A limb policy trained in tendril, deployed along a path through the safety filter (seed 001
// §5.2 and eq. 6.5), on the twin and through the real firmware in simavr. With the emulator in
// lockstep the two runs must agree bit for bit, as the other hardware-in-the-loop runs do
// (limb_hil_test.cpp): the same readings give the same observations, the same policy samples,
// the same critic values and so the same interventions and throttles.
//
// The policy and the critic are trained for seconds in SmaLimb/LearnedReach-v0 on its torch-free
// stand-in model; their quality does not matter here, only that the bridge hands them what the
// twin does. The critic is a SAC agent's twin Q-functions and actor (SacSafetyCritic) trained on
// the reaching reward, not on seed 001's safety reward: its values are not safety values, but
// the filter reads it as it reads a co-trained one, and its threshold ε₂ (the median of its
// values along an unfiltered run) makes the filter take both of its branches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "limb_hil_support.hpp"
#include "tendril/control/reference_patterns.hpp"
#include "tendril/control/tracking_policy.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/runner/tracking_record.hpp"
#include "tendril/envs/sma_limb/learned_reach_task.hpp"
#include "tendril/envs/sma_limb/policy_tracking_controller.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"
#include "tendril/safety/filtered_policy.hpp"
#include "tendril/safety/safety_critic.hpp"

namespace tendril::hardware {
namespace {

using envs::sma_limb::LearnedReachOptions;
using testing::bridge_env_params;
using testing::emulator_settings;

// One control step as the filtered policy saw and decided it.
struct FilteredStep {
  Observation observation;
  Action action;  // what the filter passed on (the policy's or the critic's)
  bool intervened = false;
};

// The filtered policy, keeping each of its decisions.
class RecordedPolicy final : public Policy {
 public:
  explicit RecordedPolicy(const safety::FilteredPolicy& filtered) : filtered_(filtered) {}
  const Space& observation_space() const override { return filtered_.observation_space(); }
  const Space& action_space() const override { return filtered_.action_space(); }
  void begin_episode(const Observation& observation) const override {
    filtered_.begin_episode(observation);
  }
  Action act(const Observation& observation, bool deterministic, Rng& rng) const override {
    Action action = filtered_.act(observation, deterministic, rng);
    steps.push_back({observation, action, filtered_.filter().last_intervened()});
    return action;
  }
  mutable std::vector<FilteredStep> steps;

 private:
  const safety::FilteredPolicy& filtered_;
};

// The policy and the critic as `tendril run --filter` deploys them: read back from their files.
struct Deployed {
  std::unique_ptr<rl::Policy> policy;
  std::unique_ptr<safety::SafetyCritic> critic;
};

Deployed train_policy_and_critic() {
  rl::VecEnvOptions options;
  options.id = "SmaLimb/LearnedReach-v0";
  const Config algo = Config::parse(
      "{net_arch: [32, 32], learning_starts: 200, batch_size: 64, buffer_size: 5000}");
  auto task_env = rl::make_vec_env(options);
  rl::Sac task(*task_env, rl::SacConfig::from_config(algo), 1);
  task.learn(3000);
  auto critic_env = rl::make_vec_env(options);
  rl::Sac critic_agent(*critic_env, rl::SacConfig::from_config(algo), 2);
  critic_agent.learn(1000);

  const auto directory = std::filesystem::temp_directory_path() / "tendril_limb_policy_hil_test";
  std::filesystem::create_directories(directory);
  task.policy().save(directory / "model.policy");
  safety::SacSafetyCritic(critic_agent.policy(), critic_agent.critics())
      .save(directory / "safety.critic");
  return {rl::load_policy(directory / "model.policy"),
          safety::load_safety_critic(directory / "safety.critic")};
}

struct FilteredRun {
  envs::TrackingRun run;
  std::vector<FilteredStep> steps;
  int64_t decisions = 0, interventions = 0;
};

constexpr int kMaxSteps = 250;
constexpr uint64_t kSeed = 3;  // of the limb's resets

FilteredRun track_through_filter(Env& limb_env, const Deployed& deployed, double epsilon,
                                 const Eigen::Matrix2Xd& path) {
  const safety::FilteredPolicy filtered(*deployed.policy, *deployed.critic, epsilon);
  auto recorded = std::make_shared<RecordedPolicy>(filtered);
  // The reaching observation of the state with the follower's point as the goal, the filtered
  // policy's throttles rounded to whole throttles, as the firmware takes them; sampled (the
  // thesis' deployed policy samples) from a stream reseeded with 17 at the path's start.
  const control::TrackingPolicy tracking = testing::raw_reading_tracking(
      limb_env,
      std::make_shared<envs::sma_limb::PolicyTrackingController>(recorded, LearnedReachOptions{},
                                                                 /*deterministic=*/false, 17),
      path);
  FilteredRun result;
  result.run = envs::track_path(tracking, limb_env, kMaxSteps, kSeed);
  result.steps = recorded->steps;
  result.decisions = filtered.filter().decisions();
  result.interventions = filtered.filter().interventions();
  return result;
}

TEST(LimbHil, ATrainedPolicyThroughTheSafetyFilterTracksThroughTheFirmwareAsOnTheTwin) {
  const Deployed deployed = train_policy_and_critic();
  // Nominal PWM table and raw readings on both paths, as the bridge settings have them.
  const Config twin_params = Config::parse("limb: stiff\ncalibration: none");
  // The spiral (two turns outward, 50°) centred where the limb rests after its reset (the stiff
  // twin rests bent by some 16°), so that the run is on the path from its first step and the
  // tracking error covers every step.
  Eigen::Matrix2Xd path = control::reference_pattern("spiral");
  {
    const Observation rest = envs::make("SmaLimb/Robot-v0", twin_params)->reset(kSeed);
    path.colwise() += Eigen::Vector2d(rest[0], rest[1]);
  }

  // ε₂: the median of the critic's values of the policy's own actions along an unfiltered run
  // on the twin (a threshold below every value never intervenes).
  double epsilon = 0.0;
  {
    auto twin = envs::make("SmaLimb/Robot-v0", twin_params);
    const FilteredRun open =
        track_through_filter(*twin, deployed, -std::numeric_limits<double>::infinity(), path);
    ASSERT_EQ(open.interventions, 0);
    std::vector<double> values;
    for (const FilteredStep& step : open.steps) {
      values.push_back(deployed.critic->value(step.observation, step.action));
    }
    ASSERT_GE(values.size(), 100u);
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    epsilon = values[values.size() / 2];
  }

  auto twin = envs::make("SmaLimb/Robot-v0", twin_params);
  const FilteredRun expected = track_through_filter(*twin, deployed, epsilon, path);

  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto bridged = envs::make("SmaLimb/Robot-v0", bridge_env_params(emulator.port()));
  const FilteredRun got = track_through_filter(*bridged, deployed, epsilon, path);
  emulator.stop();

  // Both of the filter's branches were taken on the twin, at the steps the bridge took them.
  ASSERT_EQ(expected.decisions, static_cast<int64_t>(expected.steps.size()));
  EXPECT_GT(expected.interventions, 0);
  EXPECT_LT(expected.interventions, expected.decisions);
  EXPECT_EQ(got.decisions, expected.decisions);
  EXPECT_EQ(got.interventions, expected.interventions);
  ASSERT_EQ(got.steps.size(), expected.steps.size());
  for (size_t k = 0; k < got.steps.size(); ++k) {
    ASSERT_TRUE(got.steps[k].observation == expected.steps[k].observation) << "step " << k;
    ASSERT_TRUE(got.steps[k].action == expected.steps[k].action) << "step " << k;
    ASSERT_EQ(got.steps[k].intervened, expected.steps[k].intervened) << "step " << k;
  }
  EXPECT_EQ(got.run.times, expected.run.times);
  EXPECT_EQ(got.run.angles, expected.run.angles);
  EXPECT_EQ(got.run.goals, expected.run.goals);
  EXPECT_EQ(got.run.throttles, expected.run.throttles);
  EXPECT_EQ(got.run.finished, expected.run.finished);
  // On the path from the first step, so the tracking error covers the whole run.
  EXPECT_EQ(expected.run.first_on_path, 0);
  EXPECT_EQ(got.run.first_on_path, 0);
  EXPECT_TRUE(std::isfinite(expected.run.rmse_deg));
  EXPECT_EQ(got.run.rmse_deg, expected.run.rmse_deg);
  // The limb moved: the throttles were not all zero and the bend left its rest (the path's
  // first point) by more than the follower's 10°.
  EXPECT_GT(expected.run.throttles.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT((expected.run.angles.colwise() - path.col(0)).colwise().norm().maxCoeff(), 10.0);
  // The firmware served every reading the run stepped on.
  EXPECT_GE(emulator.readings(), static_cast<int>(got.steps.size()));
}

}  // namespace
}  // namespace tendril::hardware
