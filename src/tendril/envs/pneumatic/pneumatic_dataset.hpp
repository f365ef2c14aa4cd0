#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tendril::data {
struct TableSchema;
}

namespace tendril::envs::pneumatic {

// A recording of the pneumatic arm (seed 002 §III-C: "tip movements of all three modules …
// for a dynamically saturating pressure signal for 10 min (6000 points at 10 Hz)"), in the one
// data-set format of every robot (core/data_table.hpp): CSV with a commented header that carries
// the format, the columns, the metadata and a CRC-32C of the file, so any CSV reader that skips '#'
// lines takes it, and tendril refuses it when changed, damaged or cut short.
//
//   # format: tendril.pneumatic_arm.data_set v2        (… _without_pressures v2: no pressures)
//   # column time_s: …                                  (one line per column)
//   # <key>: <value>                                    (metadata: the command, the robot, the
//   # ...                                                rows, the command ceiling, the config)
//   # crc32c: <8 hex digits>
//   time_s,command_m1_c1_bar,…,command_m3_c3_bar[,pressure_m1_c1_bar,…,pressure_m3_c3_bar],tip_m1_x_mm,tip_m1_y_mm,tip_m1_z_mm,…,tip_m3_z_mm
//   0,0.53,…
//
// Row k: time_s = t_k (s since the recording began, strictly increasing); the tip positions
// measured at t_k (mm, robot frame: origin on the base plane, z negative downward; module 1 is
// at the base) and, when present, the chamber pressures the regulators measured at t_k (bar);
// and the commands (bar) sent at t_k and held until t_{k+1}. So x_{k+1} is the response to
// command_k, as in the seed's model x_{t+1} = F(x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}).
// Modules and chambers count from 1 in column names (the paper's counting); chamber c of module
// m is flat index 3 (m − 1) + (c − 1) in the matrices below. Numbers are written as the shortest
// text that reads back exactly, so a file reads back bit for bit.
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

// The regulators' range (seed 002: 0 to 1.5 bar) when a data set's metadata names no
// `command_ceiling_bar`.
inline constexpr double kDefaultCommandCeilingBar = 1.5;

// The two layouts: with the measured pressures and without.
const data::TableSchema& pneumatic_dataset_schema(bool with_pressures);

// The header line's column names, in order.
std::vector<std::string> pneumatic_dataset_columns(bool with_pressures);

// Writes `data` atomically with its checksum. Raises tendril::Error, writing nothing, if `file`
// exists, if the matrices disagree in rows, if a value is not finite, if times do not increase,
// if a command lies outside [0, ceiling] (the metadata's command_ceiling_bar, else 1.5 bar), if
// the metadata's `rows` disagrees with the rows, or if a metadata key or value is unfit for a
// one-line "# key: value" (empty key, ':' or a line break in the key, a line break in the value).
void write_pneumatic_dataset(const std::filesystem::path& file, const PneumaticDataset& data);

// Reads a data set file strictly (data::read_table: format, columns, every number, the checksum,
// a file cut short), then checks what the numbers must satisfy: at least one row, time
// increasing, every command within [0, ceiling], and as many rows as its `rows` line says.
// Anything else raises tendril::Error naming "<file>:<line>" and what was wrong. A file of the
// earlier format without a checksum ("# tendril pneumatic-arm data set v1") is refused with how
// to collect it again.
PneumaticDataset read_pneumatic_dataset(const std::filesystem::path& file);

}  // namespace tendril::envs::pneumatic
