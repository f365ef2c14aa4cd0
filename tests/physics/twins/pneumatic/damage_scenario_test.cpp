#include "tendril/physics/twins/pneumatic/damage_scenario.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {
namespace {

int count(const std::array<bool, kChambers>& disabled) {
  int n = 0;
  for (bool d : disabled) n += d;
  return n;
}

// Seed 002 §V-A: S1–S3 disrupt one chamber in module 1, 2, 3; S4 one in module 1 and one in 2.
TEST(DamageScenario, EachScenarioDisablesThePapersChambers) {
  EXPECT_EQ(count(disabled_chambers(DamageScenario::kS0)), 0);
  for (int chamber = 0; chamber < kChambersPerModule; ++chamber) {
    for (int module = 0; module < kModules; ++module) {
      const auto scenario = static_cast<DamageScenario>(module + 1);
      const auto disabled = disabled_chambers(scenario, chamber);
      EXPECT_EQ(count(disabled), 1);
      EXPECT_TRUE(disabled[chamber_index(module, chamber)]) << to_string(scenario);
    }
    const auto both = disabled_chambers(DamageScenario::kS4, chamber);
    EXPECT_EQ(count(both), 2);
    EXPECT_TRUE(both[chamber_index(0, chamber)]);
    EXPECT_TRUE(both[chamber_index(1, chamber)]);
  }
  EXPECT_THROW(disabled_chambers(DamageScenario::kS1, 3), Error);
}

TEST(DamageScenario, NamesRoundTripAndUnknownNamesAreRefused) {
  for (int s = 0; s <= 4; ++s) {
    const auto scenario = static_cast<DamageScenario>(s);
    EXPECT_EQ(parse_damage_scenario(to_string(scenario)), scenario);
  }
  EXPECT_THROW(parse_damage_scenario("S5", "env.params.scenario"), Error);
  EXPECT_THROW(parse_damage_scenario("s1"), Error);
}

}  // namespace
}  // namespace tendril::physics::pneumatic
