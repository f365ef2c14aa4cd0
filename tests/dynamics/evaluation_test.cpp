#include "tendril/dynamics/evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"
#include "synthetic_limb.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

using testing::small_description;

TEST(Evaluation, GroupsAnglesAndVelocities) {
  const auto groups = state_groups({"theta_x", "theta_y", "omega_x", "omega_y"});
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].name, "angle");
  EXPECT_EQ(groups[0].columns, (std::vector<int>{0, 1}));
  EXPECT_EQ(groups[1].unit, "deg/s");
  EXPECT_EQ(groups[1].columns, (std::vector<int>{2, 3}));
  const auto arm = state_groups({"x1", "y1"});
  ASSERT_EQ(arm.size(), 2u);
  EXPECT_EQ(arm[1].name, "y1");
}

// Eq. (4.12) by hand: a window of recorded rows, then each prediction written into the newest
// row, the recorded input beside it, and the window shifted — one env at a time.
TEST(Evaluation, RolloutEqualsAHandWrittenLoopOfOneStepPredictions) {
  const SequenceData data = testing::SyntheticLimb{}.generate(60, 5);
  for (Architecture kind : testing::kAllArchitectures) {
    SCOPED_TRACE(architecture_name(kind));
    Model model(small_description(kind), 3);
    const int n = model.window_length();
    const int64_t start = 20, steps = 25;
    envs::BatchMatrix window(1, n * 6);
    for (int k = 0; k < n; ++k) {
      const int64_t t = start - (n - 1) + k;
      for (int c = 0; c < 4; ++c) window(0, k * 6 + c) = static_cast<float>(data.states(t, c));
      for (int c = 0; c < 2; ++c) window(0, k * 6 + 4 + c) = static_cast<float>(data.inputs(t, c));
    }
    RowMatrixXd by_hand(steps, 4);
    envs::BatchMatrix next;
    for (int64_t s = 0; s < steps; ++s) {
      model.predict(window, next);
      by_hand.row(s) = next.row(0).cast<double>();
      envs::BatchMatrix shifted(1, n * 6);
      shifted.leftCols((n - 1) * 6) = window.rightCols((n - 1) * 6);
      shifted.block(0, (n - 1) * 6, 1, 4) = next;
      for (int c = 0; c < 2; ++c) {
        shifted(0, (n - 1) * 6 + 4 + c) = static_cast<float>(data.inputs(start + s + 1, c));
      }
      window = shifted;
    }
    const std::vector<RowMatrixXd> rolled = rollouts(model, data, {start}, {steps});
    EXPECT_EQ(rolled[0], by_hand);
    // Batched with other starts, the same rollout agrees to float rounding.
    const std::vector<RowMatrixXd> batched = rollouts(model, data, {10, start, 30}, {5, steps, 7});
    EXPECT_LT((batched[1] - by_hand).cwiseAbs().maxCoeff(), 1e-3);
  }
}

TEST(Evaluation, OneStepErrorsAreTheRmseOfEachGroup) {
  const SequenceData data = testing::SyntheticLimb{}.generate(40, 6);
  Model model(small_description(Architecture::kLstm), 3);
  const WindowSet windows(data, model, 1.0);
  const ErrorReport report = one_step_errors(model, windows, Split::kTest, 3);
  const auto& ends = windows.ends(Split::kTest);
  ASSERT_EQ(report.points, static_cast<int64_t>(ends.size()));
  double angle = 0.0, velocity = 0.0;
  for (int64_t t : ends) {
    const torch::Tensor predicted = model.predict(windows.windows(std::vector<int64_t>{t}));
    for (int c = 0; c < 4; ++c) {
      const double error =
          predicted[0][c].item<double>() - static_cast<float>(data.states(t + 1, c));
      (c < 2 ? angle : velocity) += error * error;
    }
  }
  const double count = 2.0 * static_cast<double>(ends.size());
  EXPECT_NEAR(report.rmse[0], std::sqrt(angle / count), 1e-5 * report.rmse[0]);
  EXPECT_NEAR(report.rmse[1], std::sqrt(velocity / count), 1e-5 * report.rmse[1]);
}

// A model whose predictions are not finite has no error to report: "RMSE nan" is refused.
TEST(Evaluation, PredictionsThatAreNotFiniteAreAnErrorNotAnRmse) {
  const SequenceData data = testing::SyntheticLimb{}.generate(40, 6);
  Model model(small_description(Architecture::kLstm), 3);
  {
    torch::NoGradGuard no_grad;
    model.network().parameters().front().view(-1)[0] = std::nanf("");
  }
  const WindowSet windows(data, model, 1.0);
  EXPECT_NE(testing::error_message([&] {
              one_step_errors(model, windows, Split::kTest, 3);
            }).find("predictions of angle are not finite"),
            std::string::npos);
  EXPECT_NE(testing::error_message([&] {
              rollout_errors(model, data, Split::kTest, 2.0, 1.0);
            }).find("are not finite"),
            std::string::npos);
}

TEST(Evaluation, RolloutsCutEachTestSegmentIntoPiecesOfTheHorizon) {
  SequenceData data = testing::SyntheticLimb{}.generate(100, 6);
  for (int t = 0; t < 100; ++t) data.time(t) = 0.1 * t;  // the test split: rows 80–99
  Model model(small_description(Architecture::kRnn), 3);
  // Window 5: the first start is row 84; pieces of 0.5 s = 5 steps: 84→89→94→99.
  const ErrorReport pieces = rollout_errors(model, data, Split::kTest, 0.5 + 1e-9, 1.0);
  EXPECT_EQ(pieces.rollouts, 3);
  EXPECT_EQ(pieces.points, 15);
  const ErrorReport whole = rollout_errors(model, data, Split::kTest, 1800.0, 1.0);
  EXPECT_EQ(whole.rollouts, 1);
  EXPECT_EQ(whole.points, 15);
}

// Progress lines: each measurement reports a share done that grows after every model call and
// reaches 1 with its last one (a batch of 3 windows; the longest of 3 pieces of 5 steps).
TEST(Evaluation, ProgressGrowsToOneOverTheModelCalls) {
  SequenceData data = testing::SyntheticLimb{}.generate(100, 6);
  for (int t = 0; t < 100; ++t) data.time(t) = 0.1 * t;
  Model model(small_description(Architecture::kRnn), 3);
  const WindowSet windows(data, model, 1.0);
  for (const bool rollout : {false, true}) {
    std::vector<double> shares;
    const Progress record = [&shares](double done) { shares.push_back(done); };
    const ErrorReport report =
        rollout ? rollout_errors(model, data, Split::kTest, 0.5 + 1e-9, 1.0, record)
                : one_step_errors(model, windows, Split::kTest, 3, {}, record);
    const int64_t calls = rollout ? 5 : (report.points + 2) / 3;
    ASSERT_EQ(static_cast<int64_t>(shares.size()), calls) << "rollout " << rollout;
    for (std::size_t k = 1; k < shares.size(); ++k) EXPECT_GT(shares[k], shares[k - 1]);
    EXPECT_GT(shares.front(), 0.0);
    EXPECT_EQ(shares.back(), 1.0);
  }
}

// "Predict no change" on a ramp θ = c·t, ω = c, at 0.1 s a row: one step ahead every angle error
// is c·0.1 and every rate error 0; over a piece of k steps held at its start the angle errors
// are c·0.1·j, j = 1 … k, so RMSE = c·0.1·√((k + 1)(2k + 1)/6).
TEST(Evaluation, PersistenceIsTheErrorOfPredictingNoChange) {
  SequenceData data = testing::SyntheticLimb{}.generate(100, 6);
  const double c = 3.0;
  for (int t = 0; t < 100; ++t) {
    data.time(t) = 0.1 * t;
    data.states.row(t) << c * data.time(t), -c * data.time(t), c, -c;
    data.inputs.row(t) << (t % 10 == 0 ? 1.0 : 0.0), 0.0;  // a change at t = 10k and 10k + 1
  }
  Model model(small_description(Architecture::kRnn), 3);  // window 5
  const WindowSet windows(data, model, 1.0);
  const ErrorReport one_step = persistence_one_step_errors(data, windows, Split::kTest);
  EXPECT_EQ(one_step.points, static_cast<int64_t>(windows.ends(Split::kTest).size()));
  EXPECT_NEAR(one_step.rmse[0], c * 0.1, 1e-12);
  EXPECT_EQ(one_step.rmse[1], 0.0);
  // Pieces of 5 steps, as the model's rollouts (rows 84→89→94→99).
  const ErrorReport held = persistence_rollout_errors(data, Split::kTest, 0.5 + 1e-9, 1.0, 5);
  EXPECT_EQ(held.rollouts, 3);
  EXPECT_EQ(held.points, 15);
  EXPECT_NEAR(held.rmse[0], c * 0.1 * std::sqrt(6.0 * 11.0 / 6.0), 1e-9);
  // The filter keeps the windows whose last 3 rows saw an input change: t = 10k … 10k + 3.
  const PointFilter changing = [&](int64_t t) { return input_changed_within(data, t, 3); };
  for (int64_t t : {80, 81, 82, 83}) EXPECT_TRUE(changing(t)) << t;
  for (int64_t t : {84, 89, 94}) EXPECT_FALSE(changing(t)) << t;
  const ErrorReport near = persistence_one_step_errors(data, windows, Split::kTest, changing);
  const ErrorReport steady = persistence_one_step_errors(data, windows, Split::kTest,
                                                         [&](int64_t t) { return !changing(t); });
  EXPECT_EQ(near.points + steady.points, one_step.points);
  EXPECT_GT(near.points, 0);
  // The model's one-step errors split the same way and pool back to the whole.
  const ErrorReport all = one_step_errors(model, windows, Split::kTest, 7);
  const ErrorReport model_near = one_step_errors(model, windows, Split::kTest, 7, changing);
  const ErrorReport model_steady =
      one_step_errors(model, windows, Split::kTest, 7, [&](int64_t t) { return !changing(t); });
  EXPECT_EQ(model_near.points, near.points);
  for (int g = 0; g < 2; ++g) {
    const double pooled = (model_near.rmse[g] * model_near.rmse[g] * model_near.points +
                           model_steady.rmse[g] * model_steady.rmse[g] * model_steady.points) /
                          static_cast<double>(all.points);
    EXPECT_NEAR(std::sqrt(pooled), all.rmse[g], 1e-6 * all.rmse[g]);
  }
}

}  // namespace
}  // namespace tendril::dynamics
