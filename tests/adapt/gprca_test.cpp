#include "tendril/adapt/gprca.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

// A scripted 2-D plant x' = x + gain·B τ with B a fixed mixing matrix, a model of it
// x̂' = x + B τ + bias fed the plant's real state, and a policy that steps towards a goal
// through the model's inverse, with a wobble so that the actions keep varying.
struct ScriptedPlant {
  Eigen::Matrix2d mixing{{0.10, 0.02}, {-0.03, 0.08}};
  Eigen::Vector2d goal{1.0, -0.5};
  Eigen::Vector2d bias{0.0, 0.0};
  double gain = 1.0;
  Eigen::Vector2d state{0.0, 0.0};
  int time = 0;

  CompensationLoop loop() {
    CompensationLoop loop;
    loop.policy = [this](const Eigen::VectorXd& s) -> Eigen::VectorXd {
      const Eigen::Vector2d wobble(std::sin(0.7 * time), std::cos(0.4 * time));
      const Eigen::Vector2d toward = mixing.inverse() * (0.3 * (goal - s)) + 0.5 * wobble;
      return toward.cwiseMax(-1.0).cwiseMin(1.0);
    };
    loop.model = [this](const Eigen::VectorXd& x, const Eigen::VectorXd&,
                        const Eigen::VectorXd& action) -> Eigen::VectorXd {
      return x + mixing * action + bias;
    };
    loop.reset = [this]() -> Eigen::VectorXd {
      state.setZero();
      time = 0;
      return state;
    };
    loop.step = [this](const Eigen::VectorXd& action) -> Eigen::VectorXd {
      state += gain * mixing * action;
      ++time;
      return state;
    };
    return loop;
  }
};

TEST(Gprca, LearnsAConstantModelBiasAndCancelsIt) {
  ScriptedPlant plant;
  plant.bias << 0.3, -0.2;  // the model's next state is off by this on every step
  CompensationOptions options;
  options.steps_per_episode = 50;
  GprcaCompensator compensator(2, 2, options);
  const CompensationLoop loop = plant.loop();
  const auto first = compensator.run_episode(loop);
  const auto second = compensator.run_episode(loop);
  ASSERT_EQ(first.size(), 50u);
  EXPECT_EQ(compensator.retrains(), 20);
  // Before the first retrain the policy sees the raw observation.
  for (int t = 0; t < 5; ++t) EXPECT_EQ(first[t].compensation, Eigen::Vector2d::Zero());
  // Afterwards the compensated observation s = x + c is the model's prediction for the step
  // that led there: c_{t+1} = x̂_{t+1} − x_{t+1} = bias.
  for (size_t t = 1; t < second.size(); ++t) {
    const Eigen::VectorXd seen = second[t].observation + second[t].compensation;
    const Eigen::VectorXd raw_gap = second[t - 1].prediction - second[t].observation;
    EXPECT_NEAR(raw_gap.norm(), plant.bias.norm(), 1e-12);
    EXPECT_LT((second[t - 1].prediction - seen).norm(), 0.01 * plant.bias.norm()) << t;
  }
}

TEST(Gprca, LearnsAnActionDependentMismatch) {
  // The robot moves 30 % less than the model says: e = 0.3·B τ, a function of the action.
  ScriptedPlant plant;
  plant.gain = 0.7;
  CompensationOptions options;
  options.steps_per_episode = 60;
  GprcaCompensator compensator(2, 2, options);
  const CompensationLoop loop = plant.loop();
  for (int episode = 0; episode < 3; ++episode) compensator.run_episode(loop);
  for (const Eigen::Vector2d& action : {Eigen::Vector2d(0.5, -0.3), Eigen::Vector2d(-0.2, 0.6)}) {
    const Eigen::Vector2d expected = 0.3 * plant.mixing * action;
    EXPECT_LT((compensator.compensation(action) - expected).norm(), 0.05 * expected.norm());
  }
}

TEST(Gprca, SearchScheduleAndReproducibility) {
  ScriptedPlant plant;
  plant.bias << 0.1, 0.1;
  CompensationOptions options;
  options.steps_per_episode = 23;  // 4 retrains and 3 pending points carried into the next
  options.search_every = 2;
  options.seed = 5;
  GprcaCompensator a(2, 2, options), b(2, 2, options);
  const CompensationLoop loop = plant.loop();
  const auto run_a = a.run_episode(loop);
  const auto run_b = b.run_episode(loop);
  EXPECT_EQ(a.retrains(), 4);
  EXPECT_EQ(a.gp().size(), 20);
  int retrained = 0;
  for (size_t t = 0; t < run_a.size(); ++t) {
    EXPECT_EQ(run_a[t].action, run_b[t].action);
    EXPECT_EQ(run_a[t].compensation, run_b[t].compensation);
    retrained += run_a[t].retrained;
  }
  EXPECT_EQ(retrained, 4);
  a.run_episode(loop);
  EXPECT_EQ(a.gp().size(), 45);  // 3 carried + 23 new = 26 → 5 more retrains
  EXPECT_EQ(a.retrains(), 9);
}

TEST(Gprca, EpisodeEndsWhenFinished) {
  ScriptedPlant plant;
  CompensationLoop loop = plant.loop();
  loop.finished = [&](const Eigen::VectorXd&) { return plant.time == 7; };
  GprcaCompensator compensator(2, 2);
  EXPECT_EQ(compensator.run_episode(loop).size(), 7u);
}

TEST(Gprca, LoopFunctionsReturningBadValuesAreErrors) {
  ScriptedPlant plant;
  CompensationLoop loop = plant.loop();
  GprcaCompensator compensator(2, 2);
  loop.model = [](const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&) {
    return Eigen::VectorXd(Eigen::Vector3d::Zero());
  };
  EXPECT_NE(error_message([&] {
              compensator.run_episode(loop);
            }).find("model returned 3 values, expected 2"),
            std::string::npos);
  loop = plant.loop();
  loop.step = [](const Eigen::VectorXd&) { return Eigen::VectorXd(Eigen::Vector2d(NAN, 0.0)); };
  EXPECT_NE(
      error_message([&] { compensator.run_episode(loop); }).find("step returned non-finite values"),
      std::string::npos);
  loop.policy = nullptr;
  EXPECT_NE(error_message([&] { compensator.run_episode(loop); }).find("must all be set"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::adapt
