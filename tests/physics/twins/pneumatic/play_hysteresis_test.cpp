#include "tendril/physics/twins/pneumatic/play_hysteresis.hpp"

#include <gtest/gtest.h>

namespace tendril::physics::pneumatic {
namespace {

ChamberVector all(double value) { return ChamberVector::Constant(value); }

// A play operator of width 0.2 bar: the output lags the input by 0.1 on the way up, stays put
// while the input turns back within the band, lags by 0.1 on the way down and keeps a residual
// of 0.1 after venting.
TEST(PlayHysteresis, LoadingAndUnloadingPathsDifferByTheWidth) {
  PlayHysteresis play(0.2);
  EXPECT_DOUBLE_EQ(play.update(all(0.05))[0], 0.0);  // inside the band around 0
  EXPECT_DOUBLE_EQ(play.update(all(1.0))[0], 0.9);   // rising: p − w/2
  EXPECT_DOUBLE_EQ(play.update(all(0.85))[0], 0.9);  // turned back within the band
  EXPECT_DOUBLE_EQ(play.update(all(0.5))[0], 0.6);   // falling: p + w/2
  EXPECT_DOUBLE_EQ(play.update(all(0.0))[0], 0.1);   // residual after venting
  play.reset();
  EXPECT_EQ(play.output(), all(0.0));
}

TEST(PlayHysteresis, ZeroWidthPassesTheInputThrough) {
  PlayHysteresis play(0.0);
  ChamberVector input;
  for (int k = 0; k < kChambers; ++k) input[k] = 0.17 * k;
  EXPECT_EQ(play.update(input), input);
  EXPECT_THROW(PlayHysteresis(-0.1), Error);
}

}  // namespace
}  // namespace tendril::physics::pneumatic
