#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace tendril::dynamics {

using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

enum class Split : uint8_t { kTrain = 0, kTest = 1 };

// Rows [begin, end) of a SequenceData recorded without interruption and in one split.
struct Segment {
  int64_t begin = 0;
  int64_t end = 0;
  Split split = Split::kTrain;
  int64_t size() const { return end - begin; }
};

// A robot's recorded trajectory as a learned model trains on it: T time stamps, the T × d_x
// states and T × d_u inputs (row t: the input applied from t to t + 1), and each row's split.
// Seed 001's prepared data: states [θx, θy, θ̇x, θ̇y] in degrees and degrees per second, inputs
// the throttles [u_x, u_y] in [−10, 10] (thesis eqs. 4.1, 4.4, 4.5).
struct SequenceData {
  std::vector<std::string> state_names;
  std::vector<std::string> input_names;
  Eigen::VectorXd time;  // seconds
  RowMatrixXd states;
  RowMatrixXd inputs;
  std::vector<Split> split;
  std::string source;  // where the data came from, for messages
  // The line of `source` each row was read from (1-based), when it was read from a file;
  // empty otherwise.
  std::vector<int64_t> lines;

  int64_t rows() const { return time.size(); }
  int state_dim() const { return static_cast<int>(states.cols()); }
  int input_dim() const { return static_cast<int>(inputs.cols()); }

  // Raises Error naming `source` unless sizes agree, names match the columns, and every value
  // is finite.
  void validate() const;

  // Where row t came from, for messages: "<file>:<line>", or "<source>, row t".
  std::string where(int64_t t) const;

  // Why rows of `split` hold no run of `rows` consecutive rows that segments(max_gap) would
  // keep together: the longest run, and the first places where time steps back or jumps (for an
  // error that says where the data breaks up, e.g. rows out of order).
  std::string describe_runs(Split split, int64_t rows, double max_gap) const;

  // The median time between consecutive rows that follow each other (seconds).
  double sample_period() const;

  // Maximal runs of rows in one split whose time stamps increase by at most `max_gap` seconds
  // from row to row; a longer gap, a step back in time or a change of split starts a new one.
  // A window never spans two segments.
  std::vector<Segment> segments(double max_gap) const;
};

}  // namespace tendril::dynamics
