// SMA limb data sets: the documented columns and the checks a data set must pass.
#include "tendril/data/limb_data_set.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::data {
namespace {

using tendril::testing::error_message;

Table three_readings() {
  Table table;
  table.set("limb", "stiff");
  table.values.resize(3, 9);
  table.values << 0.0, 0.1, -0.2, 3, -1, 22, 0, 0, 18,  //
      0.063, 0.5, -0.4, 3, -1, 22, 0, 0, 18,            //
      0.121, 1.25, -0.9, 0, 0, 0, 0, 0, 0;
  return table;
}

class LimbDataSet : public tendril::testing::ScratchDirectoryTest {
 protected:
  LimbDataSet() : ScratchDirectoryTest("limb_data_set") {}
};

TEST_F(LimbDataSet, HasTheDocumentedColumnsAndRoundTrips) {
  std::vector<std::string> names;
  for (const ColumnSpec& column : limb_data_set_schema().columns) names.push_back(column.name);
  EXPECT_EQ(names, (std::vector<std::string>{"time_s", "theta_x_deg", "theta_y_deg", "u_x", "u_y",
                                             "pwm_0", "pwm_1", "pwm_2", "pwm_3"}));
  const auto file = directory_ / "set.csv";
  write_limb_data_set(file, three_readings());
  const Table back = read_limb_data_set(file);
  EXPECT_EQ(back.values, three_readings().values);
  EXPECT_EQ(back.get("limb"), "stiff");
}

// What a data set may not contain, each reported with the file and line of the row.
TEST_F(LimbDataSet, RejectsRowsThatBreakItsRules) {
  const auto file = directory_ / "good.csv";
  write_limb_data_set(file, three_readings());
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The rules themselves, on the file without its checksum line (as data from other software
  // comes): with it, any change is refused as corruption first.
  const std::size_t checksum = text.find("# crc32c: ");
  ASSERT_NE(checksum, std::string::npos);
  text.erase(checksum, text.find('\n', checksum) + 1 - checksum);
  struct Case {
    std::string from, to, expected;
  };
  // The header has 11 lines (format, 9 columns, the limb), the column names line 12.
  const std::vector<Case> cases{
      {"0.121,", "0.050,", ":15: time_s does not increase"},
      {"0.063,0.50,-0.40,3,", "0.063,0.50,-0.40,11,", ":14: throttle outside [-10, 10]"},
      {"3,-1,22,0,0,18\n0.121", "3,-1,22,0,0,300\n0.121", ":14: PWM outside [0, 255]"},
      {"0.000,0.10,-0.20,3,-1,22,0,", "0.000,0.10,-0.20,3,-1,22,5,",
       ":13: both coils of an antagonistic pair on"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string bad = text;
    ASSERT_NE(bad.find(cases[i].from), std::string::npos) << cases[i].from;
    bad.replace(bad.find(cases[i].from), cases[i].from.size(), cases[i].to);
    const auto bad_file = directory_ / ("bad" + std::to_string(i) + ".csv");
    std::ofstream(bad_file) << bad;
    const std::string message = error_message([&] { read_limb_data_set(bad_file); });
    EXPECT_NE(message.find(bad_file.string() + cases[i].expected), std::string::npos) << message;
  }
  Table table = three_readings();
  table.values(2, 0) = 0.063;
  EXPECT_NE(error_message([&] { write_limb_data_set(directory_ / "x.csv", table); }).find("row 2"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::data
