// A limb under closed-loop control observed as the learned-model env observes its own state:
// ReachObserver, fed the states of SmaLimb/LearnedReach-v0 and the throttles applied, builds the
// env's observation exactly (so a policy trained there sees on the robot what it saw in
// training), with and without the power proxy, across the window's start.
#include "tendril/envs/sma_limb/reach_observation.hpp"

#include <gtest/gtest.h>

#include "tendril/envs/sma_limb/learned_reach_env.hpp"
#include "tendril/envs/sma_limb/linear_limb_model.hpp"

namespace tendril::envs::sma_limb {
namespace {

void check_against_the_env(bool power_proxy) {
  LearnedReachOptions options;
  options.power_proxy = power_proxy;
  options.history = 5;  // the whole window of the model, as in training (100 of 100)
  options.full_reset_probability = 0.0;
  options.tolerance.dynamic = false;
  options.tolerance.end_deg = 1e-3;  // the goal is never reached: one episode throughout
  LearnedReachEnv env(std::make_shared<LinearLimbModel>(5), options, 4);
  ReachObserver observer(options);
  ASSERT_EQ(observer.observation_size(), env.observation_space().size());

  Observation observation = env.reset(4);
  const Eigen::Vector4d goal = env.task().goal(0);
  observer.reset(env.task().state(0));
  Eigen::VectorXf observed(observer.observation_size());
  Rng rng(8);
  for (int t = 0; t < 12; ++t) {
    observer.observe(goal, observed);
    ASSERT_TRUE(observed == observation) << "step " << t << "\n"
                                         << observed.transpose() << "\n"
                                         << observation.transpose();
    const Eigen::Vector2d throttles(std::round(rng.uniform(-10, 10)),
                                    std::round(rng.uniform(-10, 10)));
    observer.apply(throttles);
    const Step step = env.step(throttles.cast<float>());
    ASSERT_FALSE(step.terminated);
    observer.reached(env.task().state(0));
    observation = step.observation;
  }
}

TEST(ReachObserver, BuildsTheEnvsObservationWithPower) { check_against_the_env(true); }
TEST(ReachObserver, BuildsTheEnvsObservationWithoutPower) { check_against_the_env(false); }

}  // namespace
}  // namespace tendril::envs::sma_limb
