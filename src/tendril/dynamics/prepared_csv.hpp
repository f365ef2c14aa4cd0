#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::dynamics {

// The columns of a prepared data set file: optional '#' lines (the data layer's format, column
// and metadata lines), a header line of names, then one row per sample.
// `time_s` (seconds) and `split` (`train` or `test`) are always read; the state and input
// columns are named here. Other columns are ignored. The SMA limb's prepared files:
//   time_s,theta_x,theta_y,omega_x,omega_y,u_x,u_y,segment,split  (data/sma_limb/*_prepared.csv)
// (angles in degrees, angular velocities in degrees per second, throttles in [−10, 10]).
struct CsvColumns {
  std::vector<std::string> states{"theta_x", "theta_y", "omega_x", "omega_y"};
  std::vector<std::string> inputs{"u_x", "u_y"};
};

// Reads a prepared data set. A missing file or column, a row with the wrong number of fields,
// an unreadable or non-finite number or an unknown split raises Error naming the file, the line
// and the column.
SequenceData read_prepared_csv(const std::filesystem::path& file, const CsvColumns& columns = {});

// Writes `data` in the same format (numbers as the shortest text that reads back exactly),
// atomically; raises Error if `file` exists (nothing is overwritten).
void write_prepared_csv(const SequenceData& data, const std::filesystem::path& file);

}  // namespace tendril::dynamics
