#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril::rl {

// A random permutation of [0, size) (Fisher–Yates, drawn from `rng`) as a 1-D Long tensor.
torch::Tensor random_permutation(int64_t size, Rng& rng);

// A random permutation of [0, size) (Fisher–Yates, drawn from `rng`) cut into index tensors of
// `batch_size` rows; the last one holds the remainder when batch_size does not divide size
// (SB3's RolloutBuffer.get). The same draws as `random_permutation`.
std::vector<torch::Tensor> shuffled_minibatches(int64_t size, int64_t batch_size, Rng& rng);

}  // namespace tendril::rl
