// Data preparation against a hand-computed example (seed 001, eqs. 4.5 and 4.7).
#include "tendril/data/prepare.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/control/state_filter.hpp"

namespace tendril::data {
namespace {

// Seven readings: four, a 1.8 s gap, three more. θy stays 0; throttles are recorded as given.
Table example() {
  Table table;
  table.values.resize(7, 9);
  table.values << 0.00, 0.0, 0.0, 1, 0, 20, 0, 0, 0,  //
      0.05, 1.0, 0.0, 2, 0, 22, 0, 0, 0,              //
      0.15, 3.0, 0.0, 3, 0, 24, 0, 0, 0,              //
      0.20, 3.5, 0.0, 4, 0, 26, 0, 0, 0,              //
      2.00, 10.0, 0.0, 0, -1, 0, 0, 0, 19,            //
      2.05, 10.5, 0.0, 0, -1, 0, 0, 0, 19,            //
      2.10, 10.0, 0.0, 0, 0, 0, 0, 0, 0;
  return table;
}

// By hand, α = 0.8. Segment 0: raw ω = 0 (first), (1 − 0)/0.05 = 20, (3 − 1)/0.10 = 20,
// (3.5 − 3)/0.05 = 10; filtered θ = 0, 0.8, 0.8·3 + 0.2·0.8 = 2.56, 0.8·3.5 + 0.2·2.56 = 3.312;
// filtered ω = 0, 16, 0.8·20 + 0.2·16 = 19.2, 0.8·10 + 0.2·19.2 = 11.84.
// The gap restarts the filter: θ = 10, then 0.8·10.5 + 0.2·10 = 10.4, then 0.8·10 + 0.2·10.4 =
// 10.08; ω = 0, 0.8·10 = 8, 0.8·(−10) + 0.2·8 = −6.4.
// test_fraction 0.25: the split is at 0 + 0.75 · 2.1 = 1.575 s, so the last three rows are test.
TEST(Prepare, MatchesTheHandComputedExample) {
  PrepareSettings settings;
  settings.test_fraction = 0.25;
  const Table prepared = prepare_limb_data(example(), settings);
  ASSERT_EQ(prepared.rows(), 7);
  const double theta[7] = {0.0, 0.8, 2.56, 3.312, 10.0, 10.4, 10.08};
  const double omega[7] = {0.0, 16.0, 19.2, 11.84, 0.0, 8.0, -6.4};
  const double segment[7] = {0, 0, 0, 0, 1, 1, 1};
  const double split[7] = {kTrain, kTrain, kTrain, kTrain, kTest, kTest, kTest};
  for (int r = 0; r < 7; ++r) {
    EXPECT_NEAR(prepared.values(r, kThetaX), theta[r], 1e-12) << r;
    EXPECT_NEAR(prepared.values(r, kOmegaX), omega[r], 1e-12) << r;
    EXPECT_EQ(prepared.values(r, kThetaY), 0.0);
    EXPECT_EQ(prepared.values(r, kOmegaY), 0.0);
    EXPECT_EQ(prepared.values(r, kSegment), segment[r]) << r;
    EXPECT_EQ(prepared.values(r, kSplit), split[r]) << r;
    EXPECT_EQ(prepared.values(r, kTime), example().values(r, 0));
    EXPECT_EQ(prepared.values(r, kUx), example().values(r, 3));
    EXPECT_EQ(prepared.values(r, kUy), example().values(r, 4));
  }
  EXPECT_EQ(prepared.get("ema_alpha"), "0.8");
  EXPECT_EQ(prepared.get("split_time_s"), "1.575");
}

// A split inside a stretch of readings starts a new segment there: no window crosses it.
TEST(Prepare, TheSplitStartsANewSegment) {
  // The first four readings (0 … 0.2 s) with test_fraction 0.5: the split falls at 0.1 s,
  // between rows 1 and 2.
  PrepareSettings settings;
  settings.test_fraction = 0.5;
  Table table = example();
  table.values.conservativeResize(4, 9);
  const Table prepared = prepare_limb_data(table, settings);
  EXPECT_EQ(prepared.values(1, kSplit), kTrain);
  EXPECT_EQ(prepared.values(2, kSplit), kTest);
  EXPECT_EQ(prepared.values(2, kSegment), prepared.values(1, kSegment) + 1);
  EXPECT_EQ(prepared.values(2, kOmegaX), 0.0) << "the filter restarted";
}

// The filter a deployed policy runs gives what preparation wrote.
TEST(StateFilter, StreamsTheSameStateAsPreparation) {
  control::StateFilter filter;
  const Table data = example();
  const Table prepared = prepare_limb_data(data, PrepareSettings{});
  for (int r = 0; r < 4; ++r) {
    const Eigen::Vector4d state =
        filter.update(data.values(r, 0), Eigen::Vector2d(data.values(r, 1), data.values(r, 2)));
    for (int s = 0; s < 4; ++s) EXPECT_EQ(state[s], prepared.values(r, kThetaX + s));
  }
  EXPECT_NE(tendril::testing::error_message([&] { filter.update(0.1, Eigen::Vector2d::Zero()); }),
            "no error");
  EXPECT_NE(tendril::testing::error_message([] { control::StateFilter bad(1.5); }), "no error");
}

class PreparedFile : public tendril::testing::ScratchDirectoryTest {
 protected:
  PreparedFile() : ScratchDirectoryTest("prepared") {}
};

TEST_F(PreparedFile, RoundTripsAtTheWrittenPrecision) {
  const Table prepared = prepare_limb_data(example(), PrepareSettings{});
  write_prepared(directory_ / "prepared.csv", prepared);
  const Table back = read_prepared(directory_ / "prepared.csv");
  ASSERT_EQ(back.rows(), prepared.rows());
  EXPECT_LT((back.values - prepared.values).cwiseAbs().maxCoeff(), 5e-7);
  EXPECT_EQ(back.get("test_fraction"), "0.23");
}

}  // namespace
}  // namespace tendril::data
