#pragma once

#include <filesystem>

#include "tendril/core/data_table.hpp"

namespace tendril::data {

// A data set collected on the SMA limb (seed 001, §4.2.3; `tendril data collect`): one row per
// bend-sensor reading — its time stamp, the two angles (zero offsets removed) and what drove the
// limb from that reading to the next: the integer throttles commanded and the four PWM values
// the firmware applied (zero while its 100° cut-off held the coils off).
//   time_s       s since the robot was reset, 3 decimals (the firmware's millisecond clock)
//   theta_x_deg  bend towards +x, degrees, 2 decimals
//   theta_y_deg  bend towards +y, degrees, 2 decimals
//   u_x, u_y     throttles, integers in [−10, 10]
//   pwm_0 … pwm_3  PWM of the +x, −x, +y, −y coils, integers in [0, 255] (of 11.1 V)
// Time stamps strictly increase. Metadata name the robot, limb, collector, seed and calibration.
const TableSchema& limb_data_set_schema();

// read_table / write_table with the schema, plus the checks above (Error naming file and line
// on reading, row on writing).
Table read_limb_data_set(const std::filesystem::path& file);
void write_limb_data_set(const std::filesystem::path& file, const Table& table);

}  // namespace tendril::data
