#pragma once

#include <torch/torch.h>

#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {

// Tensor views of a finished RolloutBuffer's arrays (no copy: the buffer must outlive this),
// and gathered minibatches of them.
class BufferTensors {
 public:
  struct Batch {
    torch::Tensor observations;   // [batch, observation_size]
    torch::Tensor actions;        // [batch, action_dims]
    torch::Tensor old_log_probs;  // log π_θold(a_t|s_t) [batch]
    torch::Tensor old_values;     // V_θold(s_t) [batch]
    torch::Tensor advantages;     // Â_t [batch]
    torch::Tensor returns;        // Â_t + V_θold(s_t) [batch]

    // Rows [begin, end) of every tensor, as views.
    Batch rows(int64_t begin, int64_t end) const;
  };

  explicit BufferTensors(const RolloutBuffer& buffer);

  int64_t size() const { return all_.observations.size(0); }
  const Batch& all() const { return all_; }
  // The rows listed in `index` (a 1-D Long tensor).
  Batch select(const torch::Tensor& index) const;

 private:
  Batch all_;
};

}  // namespace tendril::rl
