#pragma once

// A finished rollout as LibTorch tensors, for the reference implementations of the on-policy
// updates, and the minibatch order those updates draw, replayed from a copy of their stream.
#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/rl/rollout_buffer.hpp"
#include "tendril/rl/rollout_minibatches.hpp"

namespace tendril::testing {

// [samples, columns], a copy.
inline torch::Tensor sample_rows(const rl::RolloutBuffer::RowMatrix& matrix) {
  return torch::from_blob(const_cast<float*>(matrix.data()), {matrix.rows(), matrix.cols()})
      .clone();
}
// [samples], a copy.
inline torch::Tensor sample_values(const Eigen::VectorXf& vector) {
  return torch::from_blob(const_cast<float*>(vector.data()), {vector.size()}).clone();
}

// The sample indices of each minibatch of one epoch: a permutation drawn from `rng` (as
// rl::RolloutMinibatches draws it) cut into consecutive blocks of `batch_size`.
inline std::vector<torch::Tensor> shuffled_minibatches(int64_t size, int64_t batch_size, Rng& rng) {
  std::vector<int64_t> order = rl::random_permutation(size, rng);
  const torch::Tensor all = torch::from_blob(order.data(), {size}, torch::kLong).clone();
  std::vector<torch::Tensor> blocks;
  for (int64_t first = 0; first < size; first += batch_size) {
    blocks.push_back(all.slice(0, first, std::min(first + batch_size, size)));
  }
  return blocks;
}

}  // namespace tendril::testing
