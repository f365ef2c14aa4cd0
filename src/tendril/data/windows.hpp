#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/data/table.hpp"

namespace tendril::data {

// Training pairs for a learned dynamics model (seed 001, §4.1.1, §4.2.3, eqs. 4.2, 4.3, 4.6):
// the input at step k is the history of the last n steps, each [θx, θy, ωx, ωy, u_x, u_y] (the
// filtered state and the throttles applied from it), and its label Δx_k = x_{k+1} − x_k, the
// change of the filtered state (θx, θy, ωx, ωy) to the next reading. A window never reaches
// across a segment (a gap in time, or the train/test boundary).
//
// Plain arrays, float at the learning boundary: `features` holds every row of the prepared
// table once (row-major, so a window is one contiguous block of history × 6 floats); window i is
// rows ends[i] − history + 1 … ends[i]; labels row i is its Δx.
struct WindowSet {
  static constexpr int kFeatures = 6;
  static constexpr int kState = 4;
  using Features = Eigen::Matrix<float, Eigen::Dynamic, kFeatures, Eigen::RowMajor>;
  using Labels = Eigen::Matrix<float, Eigen::Dynamic, kState, Eigen::RowMajor>;

  int history = 0;
  Features features;
  std::vector<int64_t> ends;
  Labels labels;

  std::size_t size() const { return ends.size(); }
  // Window i, history × 6, a view into `features`.
  Features::ConstRowsBlockXpr window(std::size_t i) const {
    return features.middleRows(ends[i] - history + 1, history);
  }
  // Copies the windows `indices` into `batch` ((indices · history) × 6, window after window)
  // and their labels into `batch_labels`, resizing both.
  void gather(const std::vector<int64_t>& indices, Features& batch, Labels& batch_labels) const;
};

// The windows of one split (kTrain or kTest, the prepared table's split values) with n = history
// (the thesis: 100). Error for a table that is not a prepared limb data set or history < 1.
WindowSet build_windows(const Table& prepared, int history, double split);

}  // namespace tendril::data
