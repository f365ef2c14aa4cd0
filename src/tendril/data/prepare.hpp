#pragma once

#include <Eigen/Core>
#include <filesystem>

#include "tendril/core/data_table.hpp"

namespace tendril::data {

// The thesis' state estimate from raw readings (seed 001, §4.2.3), one reading at a time — the
// same code prepares data sets and runs beside a deployed policy:
//   ω_k = (θ_k − θ_{k−1}) / (T_k − T_{k−1})                    eq. 4.5, real time stamps
//   x̄_k = α x_k + (1 − α) x̄_{k−1},  x = (θx, θy, ωx, ωy)      eq. 4.7 as a recursive EMA
// The first reading has ω = 0 and x̄ = x. The thesis writes eq. 4.7 as a blend of the two latest
// raw samples; its author's training code filters recursively (pandas ewm(alpha=0.8,
// adjust=False) on θ and θ̇, spec §2.3) — the form used here, in training and deployment alike.
class StateFilter {
 public:
  explicit StateFilter(double alpha = 0.8);

  void reset() { started_ = false; }
  // Takes a reading (time in s, angles in deg) and returns the filtered state
  // (θx, θy [deg], ωx, ωy [deg/s]). Time stamps must increase.
  Eigen::Vector4d update(double time_s, const Eigen::Vector2d& angles_deg);
  const Eigen::Vector4d& state() const { return filtered_; }

 private:
  double alpha_;
  bool started_ = false;
  double previous_time_ = 0.0;
  Eigen::Vector2d previous_angles_ = Eigen::Vector2d::Zero();
  Eigen::Vector4d filtered_ = Eigen::Vector4d::Zero();
};

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
