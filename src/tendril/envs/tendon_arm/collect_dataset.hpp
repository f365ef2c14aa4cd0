#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/data_table.hpp"

namespace tendril::envs::tendon_arm {

// The tendon arm's data set, in the one data-set format of every robot (core/data_table.hpp:
// CSV with a commented header naming the format, the columns, the metadata and a CRC-32C):
//
//   # format: tendril.tendon_arm.data_set v1
//   time_s,tension_1_n,…,tension_K_n,tip_x_m,tip_y_m,tip_z_m,travel_1_m,…,travel_K_m,split
//
// Row k: time_s = t_k (s since its recording began); the tip (m, lab frame: origin at the
// clamped base, z up) and the tendon travels (m, TendonArm/Robot-v0's observation) measured at
// t_k; the tensions (N) sent at t_k and held until t_{k+1}, so the tip of row k + 1 answers the
// tensions of row k; split `train` or `test`. A test recording follows the training one and its
// clock restarts at 0. It is also a prepared data set: `tendril model fit` reads it as it is
// (data.state_columns [tip_x_m, tip_y_m, tip_z_m], data.input_columns [tension_1_n, …]).
data::TableSchema dataset_schema(int tendons);

// The data protocol: random tensions held for random times (babbling), from an experiment file:
//
//   robot:
//     id: TendonArm/Robot-v0        # any environment with its interface
//     params: {}                    # its parameters (ArmSpec's keys)
//   duration_s: 300                 # the training recording, s of robot time
//   test_duration_s: 60             # then the test recording (0: none)
//   seed: 0                         # the signal's stream
//   signal: {hold_s: [0.2, 2.0]}    # each tension U[0, max], held U[hold_s] s, then redrawn
//   output: data/tendon_arm/twin.csv
//
// Writes the data set to `output` (or the file's `output`) with the resolved configuration and
// `invocation` as metadata. Raises Error, writing nothing, on a bad key or value, if the output
// exists, or if the robot ends the recording (a non-finite state).
struct CollectionReport {
  std::filesystem::path file;
  int train_rows = 0, test_rows = 0;
  double wall_seconds = 0.0;
  data::Table table;
};
CollectionReport collect_dataset(const Config& config, const std::filesystem::path& output,
                                 const std::string& invocation);

}  // namespace tendril::envs::tendon_arm
