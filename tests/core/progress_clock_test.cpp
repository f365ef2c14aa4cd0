#include "tendril/core/progress_clock.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

namespace tendril {
namespace {

TEST(DurationText, MinutesAndSecondsBelowAnHourHoursAndMinutesAbove) {
  EXPECT_EQ(duration_text(0.0), "0m00s");
  EXPECT_EQ(duration_text(65.4), "1m05s");
  EXPECT_EQ(duration_text(59.6), "1m00s");  // rounded to the second
  EXPECT_EQ(duration_text(3599.0), "59m59s");
  EXPECT_EQ(duration_text(3600.0 * 2 + 60 * 3 + 20), "2h03m");
  EXPECT_EQ(duration_text(-5.0), "0m00s");  // a late estimate never shows as negative
}

TEST(ProgressClock, ExtrapolatesTheTimeLeftFromTheShareDone) {
  EXPECT_EQ(ProgressClock::text(0.0, 12.0), "elapsed 0m12s");  // nothing done: no estimate
  // A quarter done in 12 s leaves three times as long.
  EXPECT_EQ(ProgressClock::text(0.25, 12.0), "elapsed 0m12s, ETA 0m36s");
  EXPECT_EQ(ProgressClock::text(0.9, 90.0), "elapsed 1m30s, ETA 0m10s");
  EXPECT_EQ(ProgressClock::text(1.0, 90.0), "elapsed 1m30s, ETA 0m00s");
  EXPECT_EQ(ProgressClock::text(1.5, 90.0), "elapsed 1m30s, ETA 0m00s");  // past the end: done
}

TEST(ProgressClock, CountsTheWallClockSinceItWasMade) {
  const ProgressClock clock;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GE(clock.elapsed_s(), 0.05);
}

}  // namespace
}  // namespace tendril
