#include "tendril/dynamics/window_set.hpp"

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

namespace {

torch::Tensor to_tensor(const RowMatrixXd& matrix) {
  return torch::from_blob(const_cast<double*>(matrix.data()), {matrix.rows(), matrix.cols()},
                          torch::kDouble)
      .clone();
}

}  // namespace

WindowSet::WindowSet(const SequenceData& data, const Model& model, double max_gap)
    : window_(model.spec().window) {
  require(data.state_dim() == model.state_dim() && data.input_dim() == model.input_dim(),
          "the data has " + std::to_string(data.state_dim()) + " state and " +
              std::to_string(data.input_dim()) + " input columns, the model " +
              std::to_string(model.state_dim()) + " and " + std::to_string(model.input_dim()),
          data.source);
  const int64_t rows = data.rows();
  const torch::Tensor states = to_tensor(data.states);
  rows_ = torch::cat({states, to_tensor(data.inputs)}, 1).to(torch::kFloat);
  // Row t's label uses x_{t+1}; the last row has none and is never a window end.
  const torch::Tensor next =
      torch::cat({states.narrow(0, 1, rows - 1), states.narrow(0, rows - 1, 1)}, 0);
  targets_ = model.target(states, next);
  next_states_ = next.to(torch::kFloat);
  offsets_ = torch::arange(-(window_ - 1), 1, torch::kLong);
  for (const Segment& segment : data.segments(max_gap)) {
    auto& ends = segment.split == Split::kTrain ? train_ends_ : test_ends_;
    for (int64_t t = segment.begin + window_ - 1; t + 1 < segment.end; ++t) ends.push_back(t);
  }
}

torch::Tensor WindowSet::gather(const torch::Tensor& table, std::span<const int64_t> ends) const {
  const torch::Tensor index = torch::from_blob(const_cast<int64_t*>(ends.data()),
                                               {static_cast<int64_t>(ends.size())}, torch::kLong);
  return table.index_select(0, index);
}

torch::Tensor WindowSet::windows(std::span<const int64_t> ends) const {
  const auto batch = static_cast<int64_t>(ends.size());
  const torch::Tensor index =
      (torch::from_blob(const_cast<int64_t*>(ends.data()), {batch, 1}, torch::kLong) + offsets_)
          .reshape({-1});
  return rows_.index_select(0, index).view({batch, window_, rows_.size(1)});
}

torch::Tensor WindowSet::targets(std::span<const int64_t> ends) const {
  return gather(targets_, ends);
}

torch::Tensor WindowSet::next_states(std::span<const int64_t> ends) const {
  return gather(next_states_, ends);
}

}  // namespace tendril::dynamics
