#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril::rl {

// A random permutation of [0, size) (Fisher–Yates, drawn from `rng`) cut into index tensors of
// `batch_size` rows; the last one holds the remainder when batch_size does not divide size
// (SB3's RolloutBuffer.get).
std::vector<torch::Tensor> shuffled_minibatches(int64_t size, int64_t batch_size, Rng& rng);

}  // namespace tendril::rl
