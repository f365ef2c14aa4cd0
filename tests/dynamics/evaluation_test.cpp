#include "tendril/dynamics/evaluation.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tendril::dynamics
