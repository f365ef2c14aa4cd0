#pragma once

#include <Eigen/Core>
#include <filesystem>

#include "tendril/core/data_table.hpp"

namespace tendril::data {

// Preparation filters each segment's readings with control::StateFilter (eqs. 4.5, 4.7), the
// estimate a deployed controller runs beside the limb.
struct PrepareSettings {
  double ema_alpha = 0.8;  // the thesis' α
  // The last test_fraction of the recording's time span is the test set (the thesis: 30 of
  // 130 min for the stiff limb, 10 of 40 for the soft one).
  double test_fraction = 0.23;
  // A time step longer than this starts a new segment: the filter restarts and no window spans
  // it (the author's code split trajectories at jumps over 10 s).
  double max_gap_s = 1.0;
};

// A prepared data set: the filtered state, the throttles, and where each row belongs.
//   time_s                 s, 3 decimals
//   theta_x, theta_y       filtered bend angles, deg, 6 decimals
//   omega_x, omega_y       filtered bend rates, deg/s, 6 decimals
//   u_x, u_y               throttles from this reading to the next, integers
//   segment                0, 1, …: rows of one segment are consecutive readings of one split
//   split                  train | test (by time: train first)
const TableSchema& prepared_schema();
enum PreparedColumn { kTime, kThetaX, kThetaY, kOmegaX, kOmegaY, kUx, kUy, kSegment, kSplit };
constexpr double kTrain = 0.0, kTest = 1.0;  // values of the split column

// Prepares a data set read with read_limb_data_set (Error naming the first bad setting).
Table prepare_limb_data(const Table& data_set, const PrepareSettings& settings);

Table read_prepared(const std::filesystem::path& file);
void write_prepared(const std::filesystem::path& file, const Table& table);

}  // namespace tendril::data
