#include "tendril/data/limb_data_set.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::data {

namespace {

// The first row that breaks the rules, with why; -1 if none.
std::pair<Eigen::Index, std::string> first_bad_row(const Table& table) {
  for (Eigen::Index r = 0; r < table.rows(); ++r) {
    if (r > 0 && !(table.values(r, 0) > table.values(r - 1, 0))) {
      return {r, "time_s does not increase"};
    }
    for (int c = 3; c <= 4; ++c) {
      if (std::abs(table.values(r, c)) > 10.0) return {r, "throttle outside [-10, 10]"};
    }
    for (int c = 5; c <= 8; ++c) {
      if (table.values(r, c) < 0.0 || table.values(r, c) > 255.0) {
        return {r, "PWM outside [0, 255]"};
      }
    }
    if ((table.values(r, 5) > 0 && table.values(r, 6) > 0) ||
        (table.values(r, 7) > 0 && table.values(r, 8) > 0)) {
      return {r, "both coils of an antagonistic pair on"};
    }
  }
  return {-1, ""};
}

}  // namespace

const TableSchema& limb_data_set_schema() {
  static const TableSchema schema{
      "tendril.sma_limb.data_set v1",
      {{"time_s", 3, {}, "time stamp of the bend-sensor reading, s since the robot was reset"},
       {"theta_x_deg", 2, {}, "bend towards +x, degrees (sensor zero offset removed)"},
       {"theta_y_deg", 2, {}, "bend towards +y, degrees (sensor zero offset removed)"},
       {"u_x", 0, {}, "x throttle commanded from this reading to the next, integer in [-10, 10]"},
       {"u_y", 0, {}, "y throttle commanded from this reading to the next, integer in [-10, 10]"},
       {"pwm_0", 0, {}, "PWM applied to the +x coil until the next reading, 0-255 of 11.1 V"},
       {"pwm_1", 0, {}, "PWM applied to the -x coil until the next reading, 0-255 of 11.1 V"},
       {"pwm_2", 0, {}, "PWM applied to the +y coil until the next reading, 0-255 of 11.1 V"},
       {"pwm_3", 0, {}, "PWM applied to the -y coil until the next reading, 0-255 of 11.1 V"}}};
  return schema;
}

Table read_limb_data_set(const std::filesystem::path& file) {
  Table table = read_table(file, limb_data_set_schema());
  const auto [row, why] = first_bad_row(table);
  if (row >= 0) throw Error(why, table.where(row));
  return table;
}

void write_limb_data_set(const std::filesystem::path& file, const Table& table) {
  const auto [row, why] = first_bad_row(table);
  if (row >= 0) throw Error(why, file.string() + ", row " + std::to_string(row));
  write_table(file, table, limb_data_set_schema());
}

}  // namespace tendril::data
