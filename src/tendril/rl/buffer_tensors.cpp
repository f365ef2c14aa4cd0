#include "tendril/rl/buffer_tensors.hpp"

namespace tendril::rl {

namespace {

// A read-only view: the tensors built here are never written to.
torch::Tensor view(const float* data, at::IntArrayRef sizes) {
  return torch::from_blob(const_cast<float*>(data), sizes, torch::kFloat);
}

}  // namespace

BufferTensors::BufferTensors(const RolloutBuffer& buffer) {
  const int64_t size = buffer.size();
  all_.observations = view(buffer.observations().data(), {size, buffer.observations().cols()});
  all_.actions = view(buffer.actions().data(), {size, buffer.actions().cols()});
  all_.old_log_probs = view(buffer.log_probs().data(), {size});
  all_.old_values = view(buffer.values().data(), {size});
  all_.advantages = view(buffer.advantages().data(), {size});
  all_.returns = view(buffer.returns().data(), {size});
}

BufferTensors::Batch BufferTensors::Batch::rows(int64_t begin, int64_t end) const {
  return {observations.slice(0, begin, end),  actions.slice(0, begin, end),
          old_log_probs.slice(0, begin, end), old_values.slice(0, begin, end),
          advantages.slice(0, begin, end),    returns.slice(0, begin, end)};
}

BufferTensors::Batch BufferTensors::select(const torch::Tensor& index) const {
  return {all_.observations.index_select(0, index),  all_.actions.index_select(0, index),
          all_.old_log_probs.index_select(0, index), all_.old_values.index_select(0, index),
          all_.advantages.index_select(0, index),    all_.returns.index_select(0, index)};
}

}  // namespace tendril::rl
