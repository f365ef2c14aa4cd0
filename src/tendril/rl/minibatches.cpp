#include "tendril/rl/minibatches.hpp"

#include <algorithm>
#include <numeric>

namespace tendril::rl {

torch::Tensor random_permutation(int64_t size, Rng& rng) {
  torch::Tensor permutation = torch::empty({size}, torch::kLong);
  int64_t* order = permutation.data_ptr<int64_t>();
  std::iota(order, order + size, int64_t{0});
  for (int64_t i = size - 1; i > 0; --i) {
    std::swap(order[i], order[rng.below(static_cast<uint64_t>(i) + 1)]);
  }
  return permutation;
}

std::vector<torch::Tensor> shuffled_minibatches(int64_t size, int64_t batch_size, Rng& rng) {
  const torch::Tensor permutation = random_permutation(size, rng);
  std::vector<torch::Tensor> batches;
  for (int64_t start = 0; start < size; start += batch_size) {
    batches.push_back(permutation.slice(0, start, std::min(start + batch_size, size)));
  }
  return batches;
}

}  // namespace tendril::rl
