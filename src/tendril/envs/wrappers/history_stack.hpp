#pragma once

#include <memory>
#include <optional>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Observes the last `length` inner observations concatenated, oldest first:
// [o_{t−k+1}, …, o_{t−1}, o_t] for k = length. After reset every slot holds the first
// observation (Gymnasium FrameStackObservation's "reset" padding), so the size is constant.
// The inner observation space must be a Box; the stacked Box repeats its bounds k times.
class HistoryStack : public Wrapper {
 public:
  HistoryStack(std::unique_ptr<Env> inner, int length);

  const Space& observation_space() const override { return observation_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  int length() const { return length_; }

 private:
  int length_;
  int frame_size_;
  Space observation_space_;
  Observation history_;
};

}  // namespace tendril::envs
