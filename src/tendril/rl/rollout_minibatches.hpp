#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {

// A random permutation of [0, size) (Fisher–Yates, drawn from `rng`).
std::vector<int64_t> random_permutation(int64_t size, Rng& rng);

// One minibatch of a rollout, one column per sample (views into RolloutMinibatches).
struct RolloutMinibatch {
  Eigen::Ref<const Eigen::MatrixXf> observations;      // s_t, observation_size × batch
  Eigen::Ref<const Eigen::MatrixXf> actions;           // a_t, action_dims × batch
  Eigen::Ref<const Eigen::RowVectorXf> old_log_probs;  // log π_θold(a_t|s_t)
  Eigen::Ref<const Eigen::RowVectorXf> old_values;     // V_θold(s_t)
  Eigen::Ref<const Eigen::RowVectorXf> advantages;     // Â_t, standardised if asked
  Eigen::Ref<const Eigen::RowVectorXf> returns;        // value targets Â_t + V_θold(s_t)
};

// The minibatches of one epoch over a finished rollout, as SB3's RolloutBuffer.get: the rollout
// gathered in a fresh random order, cut into consecutive blocks of `batch_size` samples (the
// last one holds the remainder). Samples are columns, so a minibatch is a block the dense
// networks read in place. PPO's update and TRPO's value fit use it. Beyond the permutation,
// allocates at construction only; the buffer must outlive this.
class RolloutMinibatches {
 public:
  RolloutMinibatches(const RolloutBuffer& buffer, int64_t batch_size);

  // Gathers the rollout in a random order drawn from `rng` (random_permutation). With
  // `normalize_advantages`, standardises the advantages of each minibatch as SB3 does:
  // Â ← (Â − mean) / (std + 1e-8) with the unbiased std; a minibatch of one is left as is.
  void shuffle(Rng& rng, bool normalize_advantages);

  int64_t count() const { return (size_ + batch_size_ - 1) / batch_size_; }
  RolloutMinibatch operator[](int64_t index) const;

 private:
  const RolloutBuffer& buffer_;
  int64_t size_, batch_size_;
  Eigen::MatrixXf observations_, actions_;
  Eigen::RowVectorXf old_log_probs_, old_values_, advantages_, returns_;
};

}  // namespace tendril::rl
