#include "tendril/envs/learned/history_windows.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/dynamics_model.hpp"

namespace tendril::envs {
namespace {

// Two envs, windows of 3 rows of [x (2), u (1)].
TEST(HistoryWindows, ResetFillsEveryRowWithTheStateAtRest) {
  HistoryWindows windows(2, 3, 2, 1);
  windows.reset(1, Eigen::Vector2f(4, 5));
  Eigen::RowVectorXf expected(9);
  expected << 4, 5, 0, 4, 5, 0, 4, 5, 0;
  EXPECT_EQ(windows.windows().row(1), expected);
  EXPECT_EQ(windows.windows().row(0), Eigen::RowVectorXf::Zero(9));
  EXPECT_EQ(windows.state(1), Eigen::Vector2f(4, 5));
}

TEST(HistoryWindows, InputsGoToTheNewestRowAndAdvanceShiftsOldestOut) {
  HistoryWindows windows(2, 3, 2, 1);
  windows.reset(0, Eigen::Vector2f(1, 2));
  windows.reset(1, Eigen::Vector2f(3, 4));
  BatchMatrix inputs(2, 1);
  inputs << 7, 8;
  windows.set_inputs(inputs);
  Eigen::RowVectorXf env0(9);
  env0 << 1, 2, 0, 1, 2, 0, 1, 2, 7;
  EXPECT_EQ(windows.windows().row(0), env0);
  BatchMatrix next(2, 2);
  next << 10, 11, 12, 13;
  windows.advance(next);
  env0 << 1, 2, 0, 1, 2, 7, 10, 11, 0;
  EXPECT_EQ(windows.windows().row(0), env0);
  Eigen::RowVectorXf env1(9);
  env1 << 3, 4, 0, 3, 4, 8, 12, 13, 0;
  EXPECT_EQ(windows.windows().row(1), env1);
  EXPECT_EQ(windows.state(1), Eigen::Vector2f(12, 13));
}

TEST(HistoryWindows, SetWindowCopiesRecordedRows) {
  HistoryWindows windows(1, 2, 1, 1);
  BatchMatrix rows(2, 2);
  rows << 1, 2, 3, 4;
  windows.set_window(0, rows);
  EXPECT_EQ(windows.windows().row(0), Eigen::RowVector4f(1, 2, 3, 4));
  EXPECT_THROW(windows.set_window(0, BatchMatrix::Zero(3, 2)), Error);
}

TEST(HistoryWindows, RejectsWrongSizesIndicesAndNonFiniteValues) {
  EXPECT_THROW(HistoryWindows(0, 3, 2, 1), Error);
  HistoryWindows windows(2, 3, 2, 1);
  EXPECT_THROW(windows.reset(2, Eigen::Vector2f(0, 0)), Error);
  EXPECT_THROW(windows.reset(0, Eigen::Vector3f(0, 0, 0)), Error);
  EXPECT_THROW(windows.reset(0, Eigen::Vector2f(NAN, 0)), Error);
  EXPECT_THROW(windows.set_inputs(BatchMatrix::Zero(1, 1)), Error);
  BatchMatrix nan_input = BatchMatrix::Zero(2, 1);
  nan_input(1, 0) = NAN;
  EXPECT_THROW(windows.set_inputs(nan_input), Error);
  EXPECT_THROW(windows.advance(BatchMatrix::Zero(2, 3)), Error);
}

TEST(HistoryWindows, SnapshotRestoresTheWindowsExactly) {
  HistoryWindows windows(2, 3, 2, 1);
  windows.reset(0, Eigen::Vector2f(0.1f, 0.2f));
  windows.reset(1, Eigen::Vector2f(0.3f, 0.4f));
  Snapshot snapshot;
  SnapshotWriter out(snapshot);
  windows.save_state(out);
  const BatchMatrix saved = windows.windows();
  windows.advance(BatchMatrix::Constant(2, 2, 9.0f));
  SnapshotReader in(snapshot);
  windows.load_state(in);
  EXPECT_EQ(windows.windows(), saved);
  HistoryWindows other(2, 4, 2, 1);
  SnapshotReader again(snapshot);
  EXPECT_THROW(other.load_state(again), Error);
}

// x_{t+1} = x_t + u_t · [1, 2]: checks that step sets inputs, predicts and advances.
class LinearModel : public DynamicsModel {
 public:
  int state_dim() const override { return 2; }
  int input_dim() const override { return 1; }
  int window_length() const override { return 3; }
  double sample_period() const override { return 0.1; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override {
    next_states.resize(windows.rows(), 2);
    for (Eigen::Index i = 0; i < windows.rows(); ++i) {
      const float u = windows(i, 8);
      next_states(i, 0) = windows(i, 6) + u;
      next_states(i, 1) = windows(i, 7) + 2 * u;
    }
  }
};

TEST(DynamicsModel, StepAppliesTheInputsAndFeedsThePredictionBack) {
  LinearModel model;
  HistoryWindows windows(2, 3, 2, 1);
  windows.reset(0, Eigen::Vector2f(0, 0));
  windows.reset(1, Eigen::Vector2f(1, 1));
  BatchMatrix inputs(2, 1), next;
  inputs << 1, -1;
  model.step(windows, inputs, next);
  model.step(windows, inputs, next);
  EXPECT_EQ(windows.state(0), Eigen::Vector2f(2, 4));
  EXPECT_EQ(windows.state(1), Eigen::Vector2f(-1, -3));
  EXPECT_EQ(next.row(1), Eigen::RowVector2f(-1, -3));
  HistoryWindows wrong(2, 4, 2, 1);
  EXPECT_THROW(model.step(wrong, inputs, next), Error);
}

}  // namespace
}  // namespace tendril::envs
