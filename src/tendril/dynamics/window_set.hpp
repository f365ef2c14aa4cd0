#pragma once

#include <torch/torch.h>

#include <span>
#include <vector>

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::dynamics {

// The supervised pairs of a data set for one model (thesis §4.2.3): the window ending at row t
// — rows t−n+1 … t of [x, u], the newest holding u_t — and its label from x_t and x_{t+1}
// (eq. 4.6: Δx_t = x_{t+1} − x_t; seed 002: x_{t+1}). Only windows whose rows t−n+1 … t+1 lie in
// one segment (no gap, one split) are used.
class WindowSet {
 public:
  // `max_gap`: seconds between rows beyond which the recording counts as interrupted.
  WindowSet(const SequenceData& data, const Model& model, double max_gap);

  // The window ends t of a split, in time order.
  const std::vector<int64_t>& ends(Split split) const {
    return split == Split::kTrain ? train_ends_ : test_ends_;
  }
  int window() const { return window_; }

  // Physical windows [B, n, row] (float) ending at `ends`.
  torch::Tensor windows(std::span<const int64_t> ends) const;
  // The model's training targets [B, d_x] for the windows ending at `ends`.
  torch::Tensor targets(std::span<const int64_t> ends) const;
  // The recorded next states x_{t+1} [B, d_x] (float).
  torch::Tensor next_states(std::span<const int64_t> ends) const;

 private:
  torch::Tensor gather(const torch::Tensor& table, std::span<const int64_t> ends) const;

  int window_;
  torch::Tensor rows_;         // [T, row]
  torch::Tensor targets_;      // [T, d_x]: row t = the label of the window ending at t
  torch::Tensor next_states_;  // [T, d_x]: row t = x_{t+1}
  torch::Tensor offsets_;      // [n]: −(n−1) … 0
  std::vector<int64_t> train_ends_, test_ends_;
};

}  // namespace tendril::dynamics
