#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tendril::envs::pneumatic {

// A recording of the pneumatic arm (seed 002 §III-C: "tip movements of all three modules …
// for a dynamically saturating pressure signal for 10 min (6000 points at 10 Hz)"), and its
// file: plain CSV that any CSV reader takes once it skips lines starting with '#'.
//
//   # tendril pneumatic-arm data set v1
//   # <key>: <value>                      (metadata, any number of lines, e.g. the command,
//   # ...                                  the robot's parameters, the signal's, the seed)
//   time_s,command_m1_c1_bar,…,command_m3_c3_bar[,pressure_m1_c1_bar,…,pressure_m3_c3_bar],tip_m1_x_mm,tip_m1_y_mm,tip_m1_z_mm,…,tip_m3_z_mm
//   0,0.53,…
//
// Row k: time_s = t_k (s since the recording began, strictly increasing); the tip positions
// measured at t_k (mm, robot frame: origin on the base plane, z negative downward; module 1 is
// at the base) and, when present, the chamber pressures the regulators measured at t_k (bar);
// and the commands (bar) sent at t_k and held until t_{k+1}. So x_{k+1} is the response to
// command_k, as in the seed's model x_{t+1} = F(x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}).
// Modules and chambers count from 1 in column names (the paper's counting); chamber c of module
// m is flat index 3 (m − 1) + (c − 1) in the matrices below.
struct PneumaticDataset {
  using Columns = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;

  std::vector<std::pair<std::string, std::string>> metadata;
  Eigen::VectorXd time_s;
  Columns commands_bar;
  Columns pressures_bar;  // no rows when the recording has no pressures
  Columns tips_mm;

  int size() const { return static_cast<int>(time_s.size()); }
  bool has_pressures() const { return pressures_bar.rows() > 0; }
  std::optional<std::string> meta(std::string_view key) const;
};

inline constexpr const char* kPneumaticDatasetTitle = "# tendril pneumatic-arm data set v1";

// The header line's column names, in order.
std::vector<std::string> pneumatic_dataset_columns(bool with_pressures);

// Writes `data` atomically (numbers as the shortest text that reads back exactly). Raises
// tendril::Error, writing nothing, if `file` exists, if the matrices disagree in rows, if a
// value is not finite, if times do not increase, or if a metadata key or value is unfit for a
// one-line "# key: value" (empty key, ':' or a line break in the key, a line break in the value).
void write_pneumatic_dataset(const std::filesystem::path& file, const PneumaticDataset& data);

// Reads a data set file strictly: the title line, metadata lines, the header with exactly one of
// the two column lists, then at least one row of finite numbers with increasing time. Anything
// else raises tendril::Error naming "<file>:<line>" and what was wrong.
PneumaticDataset read_pneumatic_dataset(const std::filesystem::path& file);

}  // namespace tendril::envs::pneumatic
