#include "tendril/dynamics/window_set.hpp"

#include <gtest/gtest.h>

#include "synthetic_limb.hpp"
#include "tendril/core/error.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

using testing::small_description;

// 12 rows; states row t = [t, 10t, 100t, 1000t], inputs [−t, 0.5t]; rows 0–7 train, 8–11 test;
// a gap after row 4.
SequenceData counting_rows() {
  SequenceData data = testing::SyntheticLimb{}.generate(12, 1);
  for (int t = 0; t < 12; ++t) {
    data.time(t) = 0.1 * t + (t >= 5 ? 10.0 : 0.0);
    data.states.row(t) << t, 10.0 * t, 100.0 * t, 1000.0 * t;
    data.inputs.row(t) << -t, 0.5 * t;
    data.split[t] = t < 8 ? Split::kTrain : Split::kTest;
  }
  return data;
}

TEST(WindowSet, WindowsStayInsideSegmentsAndEndBeforeTheLastRow) {
  const Model model(small_description(Architecture::kLstm, /*window=*/3), 1);
  const WindowSet windows(counting_rows(), model, 0.5);
  // Segments [0, 5), [5, 8), [8, 12): a window ending at t needs rows t−2 … t+1 in one segment.
  EXPECT_EQ(windows.ends(Split::kTrain), (std::vector<int64_t>{2, 3}));
  EXPECT_EQ(windows.ends(Split::kTest), (std::vector<int64_t>{10}));
}

TEST(WindowSet, WindowRowsAndDeltaLabelsAreTheRecordedOnes) {
  const Model model(small_description(Architecture::kLstm, 3), 1);
  const WindowSet windows(counting_rows(), model, 0.5);
  const std::vector<int64_t> ends{3, 10};
  const torch::Tensor w = windows.windows(ends);
  ASSERT_EQ(w.sizes(), (std::vector<int64_t>{2, 3, 6}));
  // Window ending at 3: rows 1, 2, 3 of [t, 10t, 100t, 1000t, −t, t/2].
  EXPECT_EQ(w[0][0][0].item<float>(), 1.0f);
  EXPECT_EQ(w[0][2][3].item<float>(), 3000.0f);
  EXPECT_EQ(w[0][2][4].item<float>(), -3.0f);
  EXPECT_EQ(w[1][0][5].item<float>(), 4.0f);  // row 8's u_y
  // Δx_t = x_{t+1} − x_t (eq. 4.6) = [1, 10, 100, 1000].
  const torch::Tensor labels = windows.targets(ends);
  EXPECT_TRUE(torch::equal(labels[0], torch::tensor({1.0f, 10.0f, 100.0f, 1000.0f})));
  EXPECT_TRUE(torch::equal(windows.next_states(ends)[1],
                           torch::tensor({11.0f, 110.0f, 1100.0f, 11000.0f})));
}

// Seed 002's eq. (1): the network reads (x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}) normalised, and
// learns x_{t+1} normalised.
TEST(WindowSet, Seed002InputLayoutAndNormalisedNextStateLabels) {
  const Model model(small_description(Architecture::kSoftsignLstm), 1);
  const Normalizer& n = model.description().normalizer;
  const WindowSet windows(counting_rows(), model, 0.5);
  const std::vector<int64_t> ends{3};
  const torch::Tensor input = model.network_input(windows.windows(ends));
  ASSERT_EQ(input.sizes(), (std::vector<int64_t>{1, 1, 14}));
  const SequenceData data = counting_rows();
  std::vector<double> expected;
  for (int t : {3, 2}) {
    for (int c = 0; c < 4; ++c) expected.push_back((data.states(t, c) - n.offset(c)) / n.scale(c));
  }
  for (int t : {3, 2, 1}) {
    for (int c = 0; c < 2; ++c) {
      expected.push_back((data.inputs(t, c) - n.offset(4 + c)) / n.scale(4 + c));
    }
  }
  for (int i = 0; i < 14; ++i) {
    EXPECT_NEAR(input[0][0][i].item<float>(), expected[i], 1e-5 * std::abs(expected[i]) + 1e-6)
        << "feature " << i;
  }
  const torch::Tensor label = windows.targets(ends);
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(label[0][c].item<float>(), (data.states(4, c) - n.offset(c)) / n.scale(c), 1e-4);
  }
  // And the output maps back: next_state(label) is x_{t+1}.
  const torch::Tensor back = model.next_state(label, torch::zeros({1, 4}));
  EXPECT_NEAR(back[0][3].item<float>(), 4000.0, 1e-2);
}

TEST(WindowSet, RejectsDataWithOtherColumnCounts) {
  const Model model(small_description(Architecture::kLstm, 3), 1);
  SequenceData data = counting_rows();
  data.inputs = data.inputs.leftCols(1).eval();
  data.input_names.pop_back();
  EXPECT_THROW(WindowSet(data, model, 0.5), Error);
}

}  // namespace
}  // namespace tendril::dynamics
