#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>

#include "tendril/core/rng.hpp"

namespace tendril::rl {

// The transitions an off-policy algorithm learns from, in a ring of fixed capacity (the oldest
// is overwritten first), stored as float columns: observation, action (as the algorithm sees
// it: scaled to [−1, 1], or the index of a discrete action), reward, next observation and
// whether the episode terminated there. A time-limit truncation is not a termination: its
// transition keeps `terminated` = 0 and the episode's final observation as next observation,
// so its target bootstraps from the value there (SB3's handle_timeout_termination).
//
// Memory is reserved up front but touched only as transitions arrive; sampling fills a
// caller-owned batch and allocates nothing once the batch has its size.
class ReplayBuffer {
 public:
  struct Batch {
    Eigen::MatrixXf observations;       // observation_size × batch
    Eigen::MatrixXf actions;            // action_size × batch
    Eigen::VectorXf rewards;            // batch
    Eigen::MatrixXf next_observations;  // observation_size × batch
    Eigen::VectorXf terminated;         // 1 where the episode ended by termination
  };

  ReplayBuffer(int64_t capacity, int64_t observation_size, int64_t action_size);

  void add(const Eigen::Ref<const Eigen::VectorXf>& observation,
           const Eigen::Ref<const Eigen::VectorXf>& action, float reward,
           const Eigen::Ref<const Eigen::VectorXf>& next_observation, bool terminated);

  // `batch_size` transitions drawn uniformly with replacement (SB3's sampling). The buffer must
  // not be empty.
  void sample(int64_t batch_size, Rng& rng, Batch& batch) const;

  // Transition i in storage order (the ring's slot, not its age), for inspection.
  auto observation(int64_t i) const { return observations_.col(i); }
  auto action(int64_t i) const { return actions_.col(i); }
  float reward(int64_t i) const { return rewards_[i]; }
  auto next_observation(int64_t i) const { return next_observations_.col(i); }
  bool terminated(int64_t i) const { return terminated_[i] != 0.0f; }

  int64_t size() const { return size_; }
  int64_t capacity() const { return capacity_; }
  int64_t observation_size() const { return observations_.rows(); }
  int64_t action_size() const { return actions_.rows(); }

  // Writes the stored transitions and the ring position atomically, with a CRC-32C over the
  // contents. `load` reads a file written by `save` for the same capacity and sizes; a missing,
  // truncated, corrupt or mismatching file raises Error naming the file and leaves this buffer
  // unchanged. `save` returns the checksum it stored.
  uint32_t save(const std::filesystem::path& file) const;
  void load(const std::filesystem::path& file);
  // The bytes `save` writes, and back (`where` names their source in messages).
  std::string serialize() const;
  void load_bytes(const std::string& bytes, const std::string& where);

 private:
  int64_t capacity_ = 0;
  int64_t size_ = 0;
  int64_t position_ = 0;  // where the next transition goes
  Eigen::MatrixXf observations_, actions_, next_observations_;
  Eigen::VectorXf rewards_, terminated_;
};

// The checksum stored at the end of a replay-buffer file (what `save` returned), read without
// loading or verifying the rest; raises Error if the file is missing or too short.
uint32_t replay_buffer_checksum(const std::filesystem::path& file);

}  // namespace tendril::rl
