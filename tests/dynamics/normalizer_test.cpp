#include "tendril/dynamics/normalizer.hpp"

#include <gtest/gtest.h>

#include "synthetic_limb.hpp"
#include "tendril/core/error.hpp"

namespace tendril::dynamics {
namespace {

// Rows x = [1, 3, 5 | test: 100], u = [2, 2, 2 | 7]: only the train rows count.
SequenceData three_rows() {
  SequenceData data = testing::SyntheticLimb{}.generate(4, 1);
  data.state_names = {"x"};
  data.input_names = {"u"};
  data.states.resize(4, 1);
  data.inputs.resize(4, 1);
  data.states << 1, 3, 5, 100;
  data.inputs << 2, 2, 2, 7;
  data.split = {Split::kTrain, Split::kTrain, Split::kTrain, Split::kTest};
  return data;
}

TEST(Normalizer, StandardUsesTheTrainRowsMeanAndPopulationDeviation) {
  const Normalizer n = Normalizer::fit(three_rows(), Normalization::kStandard);
  EXPECT_DOUBLE_EQ(n.offset(0), 3.0);
  EXPECT_DOUBLE_EQ(n.scale(0), std::sqrt(8.0 / 3.0));
  EXPECT_EQ(n.offset(1), 2.0);
  EXPECT_EQ(n.scale(1), 1.0);  // constant column
}

TEST(Normalizer, MinMaxMapsTheTrainRangeOntoMinusOneOne) {
  const Normalizer n = Normalizer::fit(three_rows(), Normalization::kMinMax);
  EXPECT_EQ(n.offset(0), 3.0);
  EXPECT_EQ(n.scale(0), 2.0);  // 1 → −1, 5 → +1
  EXPECT_EQ(n.offset(1), 2.0);
  EXPECT_EQ(n.scale(1), 1.0);
  const Normalizer none = Normalizer::fit(three_rows(), Normalization::kNone);
  EXPECT_EQ(none.offset, Eigen::Vector2d::Zero());
  EXPECT_EQ(none.scale, Eigen::Vector2d::Ones());
}

// Values whose mean or spread overflows are named by column, value and line, not left for the
// model to refuse as "normalisation offsets must be finite".
TEST(Normalizer, ValuesTooLargeToNormaliseAreNamedWithTheirLine) {
  SequenceData data = three_rows();
  data.source = "limb.csv";
  data.lines = {10, 11, 13, 14};
  const auto message = [&](Normalization kind) {
    try {
      Normalizer::fit(data, kind);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  data.states(1, 0) = 1e308;
  data.states(2, 0) = 1e308;  // the sum overflows
  EXPECT_EQ(message(Normalization::kStandard),
            "limb.csv:11: column 'x': its values are too large to normalise (their mean or "
            "spread overflows); the largest, 1e+308, is on this line");
  data.states(1, 0) = 1.7e308;
  data.states(2, 0) = -1.7e308;  // the sum is 1, the squares and the range overflow
  EXPECT_EQ(message(Normalization::kMinMax),
            "limb.csv:11: column 'x': its values are too large to normalise (their mean or "
            "spread overflows); the largest, 1.7e+308, is on this line");
  data.lines.clear();
  EXPECT_EQ(message(Normalization::kStandard).rfind("limb.csv, row 1: column 'x'", 0), 0u);
}

TEST(Normalizer, ValidateRejectsWrongSizesAndNonPositiveScales) {
  Normalizer n = Normalizer::identity(3);
  EXPECT_NO_THROW(n.validate(3, "here"));
  EXPECT_THROW(n.validate(4, "here"), Error);
  n.scale(1) = 0.0;
  EXPECT_THROW(n.validate(3, "here"), Error);
}

}  // namespace
}  // namespace tendril::dynamics
