// History windows and Δx labels (seed 001, eqs. 4.2, 4.3, 4.6).
#include "tendril/data/windows.hpp"

#include <gtest/gtest.h>

#include "tendril/data/prepare.hpp"

namespace tendril::data {
namespace {

// A prepared table by hand: 9 rows; segments 0 (rows 0–4, train), 1 (rows 5–6, train), 2 (rows
// 7–8, test); row r has θx = r, θy = 10 r, ωx = 100 r, ωy = −r, u = (r, −r).
Table prepared_by_hand() {
  Table table;
  table.values.resize(9, 9);
  const double segment[9] = {0, 0, 0, 0, 0, 1, 1, 2, 2};
  for (int r = 0; r < 9; ++r) {
    table.values.row(r) << 0.1 * r, r, 10.0 * r, 100.0 * r, -r, r, -r, segment[r],
        r >= 7 ? kTest : kTrain;
  }
  return table;
}

// History 3, train: a window ends at k when rows k − 2 … k and k + 1 share k's segment —
// k = 2, 3 in segment 0 (k = 4 has no next row in it; segment 1 is too short).
TEST(Windows, StayInsideOneSegmentAndSplit) {
  const WindowSet train = build_windows(prepared_by_hand(), 3, kTrain);
  EXPECT_EQ(train.ends, (std::vector<int64_t>{2, 3}));
  ASSERT_EQ(train.labels.rows(), 2);
  // Δx = x_{k+1} − x_k = (1, 10, 100, −1) for every k here.
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(train.labels.row(i), Eigen::RowVector4f(1.0f, 10.0f, 100.0f, -1.0f));
  }
  const auto window = train.window(1);  // rows 1, 2, 3
  ASSERT_EQ(window.rows(), 3);
  EXPECT_EQ(window(0, 0), 1.0f);
  EXPECT_EQ(window(2, 0), 3.0f);
  EXPECT_EQ(window(2, 4), 3.0f) << "u_x";
  EXPECT_EQ(window(2, 5), -3.0f) << "u_y";
  // History 1, test: only k = 7 (row 8 is the last).
  const WindowSet test = build_windows(prepared_by_hand(), 1, kTest);
  EXPECT_EQ(test.ends, (std::vector<int64_t>{7}));
  EXPECT_EQ(build_windows(prepared_by_hand(), 6, kTrain).size(), 0u);
}

TEST(Windows, GatherCopiesWindowsBackToBack) {
  // History 2: k = 1, 2, 3 in segment 0; in segment 1, k = 5 lacks a first row and k = 6 a next.
  const WindowSet train = build_windows(prepared_by_hand(), 2, kTrain);
  ASSERT_EQ(train.ends, (std::vector<int64_t>{1, 2, 3}));
  WindowSet::Features batch;
  WindowSet::Labels labels;
  train.gather({2, 0}, batch, labels);
  ASSERT_EQ(batch.rows(), 4);
  EXPECT_EQ(batch(0, 0), 2.0f);  // window 2: rows 2, 3
  EXPECT_EQ(batch(1, 0), 3.0f);
  EXPECT_EQ(batch(2, 0), 0.0f);  // window 0: rows 0, 1
  EXPECT_EQ(batch(3, 0), 1.0f);
  EXPECT_EQ(labels.row(1), train.labels.row(0));
  // The windows are contiguous in memory, row-major: a tensor can view them without a copy.
  EXPECT_EQ(train.window(2).data(), train.features.data() + 2 * WindowSet::kFeatures);
  EXPECT_ANY_THROW(train.gather({3}, batch, labels));
}

}  // namespace
}  // namespace tendril::data
