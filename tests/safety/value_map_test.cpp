#include "tendril/safety/value_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace tendril::safety {
namespace {

// Five grid points: value, and whether each lies in the analytic set.
ValueMap hand_made_map() {
  ValueMap map;
  map.columns = {"position", "velocity", "value", "action_0", "analytic_safe"};
  map.has_analytic_set = true;
  map.rows.resize(5, 5);
  map.rows << 0, 0, 50, 0, 1,  //
      1, 0, 10, 0, 1,          //
      1.9, 2, 5, -1, 0,        // learned safe at ε₂ < 5, outside the analytic set
      3, 0, -80, -1, 0,        //
      -1.9, -2, -1, 1, 0;
  return map;
}

TEST(ValueMap, FractionOfLearnedSafeStatesOutsideTheAnalyticSet) {
  const ValueMap map = hand_made_map();
  EXPECT_DOUBLE_EQ(map.fraction_outside_analytic(0.0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(map.fraction_outside_analytic(6.0), 0.0);
  EXPECT_TRUE(std::isnan(map.fraction_outside_analytic(60.0)));  // nothing learned safe
  ValueMap no_set = map;
  no_set.has_analytic_set = false;
  EXPECT_TRUE(std::isnan(no_set.fraction_outside_analytic(0.0)));
}

TEST(ValueMap, WritesItsGridAsCsv) {
  const auto file = std::filesystem::temp_directory_path() / "tendril_value_map_test.csv";
  hand_made_map().write_csv(file);
  std::ifstream in(file);
  std::string header, first, third;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, third);
  std::getline(in, third);
  EXPECT_EQ(header, "position,velocity,value,action_0,analytic_safe");
  EXPECT_EQ(first, "0,0,50,0,1");
  EXPECT_EQ(third, "1.9,2,5,-1,0");
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace tendril::safety
