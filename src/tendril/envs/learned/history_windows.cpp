#include "tendril/envs/learned/history_windows.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {
constexpr const char* kWhere = "envs::HistoryWindows";
}  // namespace

HistoryWindows::HistoryWindows(int num_envs, int length, int state_dim, int input_dim)
    : length_(length), state_dim_(state_dim), input_dim_(input_dim) {
  require(num_envs >= 1 && length >= 1 && state_dim >= 1 && input_dim >= 0,
          "needs num_envs, length, state_dim >= 1 and input_dim >= 0, got " +
              std::to_string(num_envs) + ", " + std::to_string(length) + ", " +
              std::to_string(state_dim) + ", " + std::to_string(input_dim),
          kWhere);
  windows_ = BatchMatrix::Zero(num_envs, static_cast<Eigen::Index>(length) * row_size());
}

void HistoryWindows::check_env(int env) const {
  if (env < 0 || env >= num_envs()) {
    throw Error(
        "env index " + std::to_string(env) + " outside [0, " + std::to_string(num_envs()) + ")",
        kWhere);
  }
}

void HistoryWindows::reset(int env, const Eigen::Ref<const Eigen::VectorXf>& state) {
  check_env(env);
  require(state.size() == state_dim_ && state.allFinite(),
          "reset needs a finite state of size " + std::to_string(state_dim_), kWhere);
  auto window = windows_.row(env);
  for (int k = 0; k < length_; ++k) {
    window.segment(k * row_size(), state_dim_) = state.transpose();
    window.segment(k * row_size() + state_dim_, input_dim_).setZero();
  }
}

void HistoryWindows::set_window(int env, const Eigen::Ref<const BatchMatrix>& rows) {
  check_env(env);
  require(rows.rows() == length_ && rows.cols() == row_size() && rows.allFinite(),
          "set_window needs finite " + std::to_string(length_) + " × " +
              std::to_string(row_size()) + " rows",
          kWhere);
  for (int k = 0; k < length_; ++k)
    windows_.row(env).segment(k * row_size(), row_size()) = rows.row(k);
}

void HistoryWindows::set_inputs(const BatchMatrix& inputs) {
  require(inputs.rows() == num_envs() && inputs.cols() == input_dim_ && inputs.allFinite(),
          "set_inputs needs finite " + std::to_string(num_envs()) + " × " +
              std::to_string(input_dim_) + " inputs",
          kWhere);
  const Eigen::Index newest = static_cast<Eigen::Index>(length_ - 1) * row_size() + state_dim_;
  windows_.middleCols(newest, input_dim_) = inputs;
}

void HistoryWindows::set_input(int env, const Eigen::Ref<const Eigen::VectorXf>& input) {
  check_env(env);
  require(input.size() == input_dim_ && input.allFinite(),
          "set_input needs a finite input of size " + std::to_string(input_dim_), kWhere);
  const Eigen::Index newest = static_cast<Eigen::Index>(length_ - 1) * row_size() + state_dim_;
  windows_.row(env).segment(newest, input_dim_) = input.transpose();
}

void HistoryWindows::advance(const BatchMatrix& next_states) {
  require(next_states.rows() == num_envs() && next_states.cols() == state_dim_,
          "advance needs " + std::to_string(num_envs()) + " × " + std::to_string(state_dim_) +
              " next states",
          kWhere);
  const Eigen::Index kept = static_cast<Eigen::Index>(length_ - 1) * row_size();
  // Shift the older rows one slot towards the front; the blocks overlap, hence eval().
  if (kept > 0) windows_.leftCols(kept) = windows_.middleCols(row_size(), kept).eval();
  windows_.middleCols(kept, state_dim_) = next_states;
  windows_.middleCols(kept + state_dim_, input_dim_).setZero();
}

Eigen::VectorXf HistoryWindows::state(int env) const {
  check_env(env);
  const Eigen::Index newest = static_cast<Eigen::Index>(length_ - 1) * row_size();
  return windows_.row(env).segment(newest, state_dim_).transpose();
}

void HistoryWindows::save_state(SnapshotWriter& out) const {
  out.section("HistoryWindows");
  out.put_matrix(windows_);
}

void HistoryWindows::load_state(SnapshotReader& in) {
  in.section("HistoryWindows");
  BatchMatrix windows(windows_.rows(), windows_.cols());
  in.get_matrix(windows);
  windows_ = windows;
}

}  // namespace tendril::envs
