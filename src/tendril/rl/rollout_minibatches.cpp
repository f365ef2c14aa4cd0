#include "tendril/rl/rollout_minibatches.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace tendril::rl {

namespace {

// Standardises `values` in place in double (one pass for the mean, one for the variance).
void standardize(float* values, int64_t size) {
  if (size < 2) return;
  const auto n = static_cast<double>(size);
  double sum = 0.0;
  for (int64_t i = 0; i < size; ++i) sum += values[i];
  const double mean = sum / n;
  double squares = 0.0;
  for (int64_t i = 0; i < size; ++i) squares += (values[i] - mean) * (values[i] - mean);
  const double scale = 1.0 / (std::sqrt(squares / (n - 1.0)) + 1e-8);
  for (int64_t i = 0; i < size; ++i) values[i] = static_cast<float>((values[i] - mean) * scale);
}

}  // namespace

std::vector<int64_t> random_permutation(int64_t size, Rng& rng) {
  std::vector<int64_t> order(static_cast<std::size_t>(size));
  std::iota(order.begin(), order.end(), int64_t{0});
  for (int64_t i = size - 1; i > 0; --i) {
    std::swap(order[i], order[rng.below(static_cast<uint64_t>(i) + 1)]);
  }
  return order;
}

RolloutMinibatches::RolloutMinibatches(const RolloutBuffer& buffer, int64_t batch_size)
    : buffer_(buffer),
      size_(buffer.size()),
      batch_size_(batch_size),
      observations_(buffer.observations().cols(), buffer.size()),
      actions_(buffer.actions().cols(), buffer.size()),
      old_log_probs_(buffer.size()),
      old_values_(buffer.size()),
      advantages_(buffer.size()),
      returns_(buffer.size()) {}

void RolloutMinibatches::shuffle(Rng& rng, bool normalize_advantages) {
  const std::vector<int64_t> order = random_permutation(size_, rng);
  for (int64_t i = 0; i < size_; ++i) {
    const int64_t row = order[i];
    observations_.col(i) = buffer_.observations().row(row).transpose();
    actions_.col(i) = buffer_.actions().row(row).transpose();
    old_log_probs_[i] = buffer_.log_probs()[row];
    old_values_[i] = buffer_.values()[row];
    advantages_[i] = buffer_.advantages()[row];
    returns_[i] = buffer_.returns()[row];
  }
  if (!normalize_advantages) return;
  for (int64_t start = 0; start < size_; start += batch_size_) {
    standardize(advantages_.data() + start, std::min(batch_size_, size_ - start));
  }
}

RolloutMinibatch RolloutMinibatches::operator[](int64_t index) const {
  const int64_t start = index * batch_size_;
  const int64_t n = std::min(batch_size_, size_ - start);
  return {observations_.middleCols(start, n), actions_.middleCols(start, n),
          old_log_probs_.segment(start, n),   old_values_.segment(start, n),
          advantages_.segment(start, n),      returns_.segment(start, n)};
}

}  // namespace tendril::rl
