#include "tendril/envs/sma_limb/learned_reach_env.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/linear_limb_model.hpp"

namespace tendril::envs::sma_limb {
namespace {

// The linear stand-in with a longer window, counting its batched calls.
class CountingModel : public DynamicsModel {
 public:
  explicit CountingModel(int window) : inner_(window) {}
  int state_dim() const override { return 4; }
  int input_dim() const override { return 2; }
  int window_length() const override { return inner_.window_length(); }
  double sample_period() const override { return inner_.sample_period(); }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override {
    ++calls;
    rows += static_cast<int>(windows.rows());
    inputs = windows.rightCols(2);  // the newest row's throttles
    inner_.predict(windows, next_states);
  }
  int calls = 0, rows = 0;
  BatchMatrix inputs;

 private:
  LinearLimbModel inner_;
};

LearnedReachOptions never_full() {
  LearnedReachOptions options;
  options.full_reset_probability = 0.0;
  return options;
}

BatchMatrix throttles(float x, float y) {
  BatchMatrix action(1, 2);
  action << x, y;
  return action;
}

TEST(LearnedReachBatch, ObservationIsStateThrottlesGoalAndPower) {
  LearnedReachBatch batch(std::make_shared<CountingModel>(5), never_full(), 1, 7);
  batch.reset(0);
  batch.step(throttles(4, -2));
  Eigen::VectorXf observation(14);
  batch.observe(0, observation);
  const Eigen::Vector4d state = batch.state(0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(observation[i], static_cast<float>(state[i]));
  EXPECT_EQ(observation[4], 4.0f);
  EXPECT_EQ(observation[5], -2.0f);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(observation[6 + i], static_cast<float>(batch.goal(0)[i]));
  EXPECT_FLOAT_EQ(observation[10], 16.0f / 3.0f * 0.075f);  // +x
  EXPECT_EQ(observation[11], 0.0f);
  EXPECT_EQ(observation[12], 0.0f);
  EXPECT_FLOAT_EQ(observation[13], 4.0f / 3.0f * 0.075f);  // −y
  EXPECT_TRUE(batch.observation_space().contains(observation));

  LearnedReachOptions without_power = never_full();
  without_power.power_proxy = false;
  LearnedReachBatch smaller(std::make_shared<CountingModel>(5), without_power, 1, 7);
  EXPECT_EQ(smaller.observation_size(), 10);
  EXPECT_EQ(smaller.observation_space().size(), 10);
}

// History rows [x_k, u_{k−1}] come from the model's window, continuing across half resets.
TEST(LearnedReachBatch, HistoryRowsAreStatesWithThePreviousThrottles) {
  LearnedReachOptions options = never_full();
  options.history = 3;
  LearnedReachBatch batch(std::make_shared<CountingModel>(4), options, 1, 2);
  EXPECT_EQ(batch.observation_size(), 14 + 18);
  batch.reset(0);
  batch.step(throttles(1, 2));
  batch.step(throttles(3, 4));
  batch.reset(0);  // half: the history stays
  batch.step(throttles(5, 6));
  Eigen::VectorXf observation(batch.observation_size());
  batch.observe(0, observation);
  const BatchMatrix& window = batch.windows().windows();
  for (int h = 0; h < 3; ++h) {
    const int k = 1 + h;  // rows 1, 2, 3 of a 4-row window
    for (int i = 0; i < 4; ++i) EXPECT_EQ(observation[14 + 6 * h + i], window(0, k * 6 + i));
  }
  EXPECT_EQ(observation.segment<2>(14 + 4), Eigen::Vector2f(1, 2));  // before x_{t−2}: u = (1, 2)
  EXPECT_EQ(observation.segment<2>(14 + 10), Eigen::Vector2f(3, 4));
  EXPECT_EQ(observation.segment<2>(14 + 16), Eigen::Vector2f(5, 6));  // u_{t−1}
  EXPECT_EQ(observation.segment<4>(14 + 12), observation.head<4>());  // newest row is x_t
  EXPECT_TRUE(batch.observation_space().contains(observation));
  options.history = 5;
  EXPECT_THROW(LearnedReachBatch(std::make_shared<CountingModel>(4), options, 1, 2), Error);
}

TEST(LearnedReachBatch, ThrottlesAreRoundedAndLimitedAsTheFirmwareTakesThem) {
  auto model = std::make_shared<CountingModel>(3);
  LearnedReachBatch batch(model, never_full(), 1, 1);
  batch.reset(0);
  batch.step(throttles(2.6f, -13.0f));
  EXPECT_EQ(model->inputs(0, 0), 3.0f);
  EXPECT_EQ(model->inputs(0, 1), -10.0f);
  EXPECT_EQ(batch.info(0).get("u_x"), 3.0);
  EXPECT_EQ(batch.info(0).get("u_y"), -10.0);

  LearnedReachOptions continuous = never_full();
  continuous.integer_throttles = false;
  LearnedReachBatch exact(model, continuous, 1, 1);
  exact.reset(0);
  exact.step(throttles(2.5f, -0.25f));
  EXPECT_EQ(model->inputs(0, 0), 2.5f);
  EXPECT_EQ(model->inputs(0, 1), -0.25f);
  EXPECT_THROW(exact.step(throttles(NAN, 0)), Error);
}

// A half reset draws a new goal and keeps the state and the whole history; a full reset starts
// at rest in a new state.
TEST(LearnedReachBatch, HalfResetKeepsTheHistoryAndFullResetStartsAfresh) {
  LearnedReachBatch batch(std::make_shared<CountingModel>(4), never_full(), 1, 3);
  batch.reset(0);
  EXPECT_EQ(batch.info(0).get("full_reset"), 1.0);  // the first reset is always full
  for (int t = 0; t < 6; ++t) batch.step(throttles(5, -3));
  const BatchMatrix history = batch.windows().windows();
  const Eigen::Vector4d goal = batch.goal(0);
  EXPECT_GT(batch.power(0).power().norm(), 0.0);
  batch.reset(0);
  EXPECT_EQ(batch.info(0).get("full_reset"), 0.0);
  EXPECT_EQ(batch.windows().windows(), history);
  EXPECT_NE(batch.goal(0), goal);
  EXPECT_EQ(batch.power(0).power(), Eigen::Vector4d::Zero());
  EXPECT_EQ(batch.simulated_steps(0), 6);  // the tolerance schedule keeps counting

  LearnedReachOptions always_full = never_full();
  always_full.full_reset_probability = 1.0;
  LearnedReachBatch fresh(std::make_shared<CountingModel>(4), always_full, 1, 3);
  fresh.reset(0);
  for (int t = 0; t < 6; ++t) fresh.step(throttles(5, -3));
  fresh.reset(0);
  EXPECT_EQ(fresh.info(0).get("full_reset"), 1.0);
  const Eigen::Vector4d start = fresh.state(0);
  EXPECT_LE(start.head<2>().cwiseAbs().maxCoeff(), 75.0);
  EXPECT_LE(start.tail<2>().cwiseAbs().maxCoeff(), 10.0);
  const BatchMatrix& rows = fresh.windows().windows();
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(rows.row(0).segment(k * 6, 4).transpose(), start.cast<float>()) << "row " << k;
    EXPECT_EQ(rows.row(0).segment(k * 6 + 4, 2).norm(), 0.0f) << "row " << k;
  }
}

// An episode that leaves the bounds cannot continue from there: the next reset is full.
TEST(LearnedReachBatch, OutOfBoundsEndsWith5000AndForcesAFullReset) {
  LearnedReachBatch batch(std::make_shared<CountingModel>(2), never_full(), 1, 5);
  batch.reset(0);
  batch.set_goal(0, Eigen::Vector4d(-70, -70, 0, 0));
  bool ended = false;
  for (int t = 0; t < 200 && !ended; ++t) {
    batch.step(throttles(10, 10));  // settles at +90°, beyond the bounds
    ended = batch.terminated(0);
  }
  ASSERT_TRUE(ended);
  EXPECT_EQ(batch.info(0).get("out_of_bounds"), 1.0);
  EXPECT_EQ(batch.info(0).get("is_success"), 0.0);
  EXPECT_LT(batch.reward(0), -5000.0);
  batch.reset(0);
  EXPECT_EQ(batch.info(0).get("full_reset"), 1.0);
  EXPECT_TRUE((batch.state(0).array().abs() <= 80.0).all());
}

// The goal is set to where the model will be after one step: the episode ends with success.
TEST(LearnedReachBatch, ReachingTheGoalTerminatesWithSuccess) {
  auto model = std::make_shared<CountingModel>(2);
  LearnedReachBatch batch(model, never_full(), 1, 9);
  batch.reset(0);
  HistoryWindows probe = batch.windows();
  BatchMatrix next;
  model->step(probe, throttles(0, 0), next);
  Eigen::Vector4d goal = next.row(0).cast<double>().transpose();
  goal[0] += 0.3;  // 0.3° away, inside the 5° starting tolerance
  batch.set_goal(0, goal);
  batch.step(throttles(0, 0));
  EXPECT_TRUE(batch.terminated(0));
  EXPECT_EQ(batch.info(0).get("is_success"), 1.0);
  EXPECT_NEAR(*batch.info(0).get("distance_deg"), 0.3, 1e-4);
  EXPECT_NEAR(*batch.info(0).get("tolerance_deg"), 5.0 - 4.0 / 8000.0, 1e-12);
  // The goal's velocity is the state's: no velocity penalty, no throttle penalty.
  EXPECT_NEAR(batch.reward(0), 1000.0 - 0.3, 1e-3);
}

// N environments step through one model call and behave exactly as N separate ones seeded
// seed + i.
TEST(LearnedReachBatch, OneBatchedCallMatchesSeparateEnvironments) {
  auto batched_model = std::make_shared<CountingModel>(3);
  LearnedReachBatch batch(batched_model, LearnedReachOptions{}, 3, 20);
  std::vector<std::unique_ptr<LearnedReachBatch>> singles;
  for (int i = 0; i < 3; ++i) {
    singles.push_back(std::make_unique<LearnedReachBatch>(std::make_shared<CountingModel>(3),
                                                          LearnedReachOptions{}, 1, 20 + i));
  }
  for (int i = 0; i < 3; ++i) {
    batch.reset(i);
    singles[i]->reset(0);
  }
  Rng rng(4);
  for (int t = 0; t < 30; ++t) {
    BatchMatrix actions(3, 2);
    for (int i = 0; i < 3; ++i) {
      actions.row(i) << static_cast<float>(rng.uniform(-10, 10)),
          static_cast<float>(rng.uniform(-10, 10));
    }
    batch.step(actions);
    for (int i = 0; i < 3; ++i) {
      singles[i]->step(actions.row(i));
      Eigen::VectorXf a(14), b(14);
      batch.observe(i, a);
      singles[i]->observe(0, b);
      ASSERT_EQ(a, b) << "env " << i << " step " << t;
      ASSERT_EQ(batch.reward(i), singles[i]->reward(0));
      if (batch.terminated(i)) {
        batch.reset(i);
        singles[i]->reset(0);
      }
    }
  }
  EXPECT_EQ(batched_model->calls, 30);
  EXPECT_EQ(batched_model->rows, 90);
}

TEST(LearnedReachEnv, IsRegisteredWith250StepsAndOpensModelsThroughTheLoader) {
  EXPECT_EQ(builtin_registry().spec(LearnedReachEnv::kId).max_episode_steps, 250);
  install_dynamics_model_loader(nullptr);
  EXPECT_NE(testing::error_message([] {
              make(LearnedReachEnv::kId, Config::parse("model: runs/some_model"));
            }).find("built without the dynamics layer"),
            std::string::npos);
  install_dynamics_model_loader([](const std::string& path) -> std::unique_ptr<DynamicsModel> {
    if (path != "scripted") throw Error("no model at " + path);
    return std::make_unique<CountingModel>(7);
  });
  auto env = make(LearnedReachEnv::kId, Config::parse("model: scripted\npower_proxy: false"));
  EXPECT_EQ(env->observation_space().size(), 10);
  env->reset(1);
  const Step step = env->step(Eigen::Vector2f(1, 1));
  EXPECT_EQ(step.observation.size(), 10);
  EXPECT_THROW(make(LearnedReachEnv::kId, Config::parse("model: elsewhere")), Error);
  EXPECT_THROW(make(LearnedReachEnv::kId, Config::parse("power_proxi: false")), Error);
  install_dynamics_model_loader(nullptr);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
