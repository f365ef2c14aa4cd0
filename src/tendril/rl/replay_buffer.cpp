#include "tendril/rl/replay_buffer.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

constexpr char kMagic[8] = {'T', 'D', 'R', 'L', 'R', 'E', 'P', 'B'};
constexpr int64_t kFormat = 1;
constexpr int kHeaderWords = 6;  // format, capacity, observation size, action size, size, position

// The first `columns` columns of a column-major matrix or vector are its first
// rows × columns floats.
template <typename Storage>
void append_columns(std::string& bytes, const Storage& storage, int64_t columns) {
  bytes.append(reinterpret_cast<const char*>(storage.data()),
               static_cast<std::size_t>(storage.rows() * columns) * sizeof(float));
}

template <typename Storage>
void read_columns(const char*& cursor, Storage& storage, int64_t columns) {
  const auto bytes = static_cast<std::size_t>(storage.rows() * columns) * sizeof(float);
  std::memcpy(storage.data(), cursor, bytes);
  cursor += bytes;
}

}  // namespace

ReplayBuffer::ReplayBuffer(int64_t capacity, int64_t observation_size, int64_t action_size)
    : capacity_(capacity) {
  require(capacity >= 1, "capacity must be at least 1", "rl::ReplayBuffer");
  require(observation_size >= 1 && action_size >= 1,
          "observation and action sizes must be positive", "rl::ReplayBuffer");
  // Refused up front when it cannot fit in memory: the pages are committed only as transitions
  // arrive, so an oversized buffer would otherwise end the process late, without a message.
  const double bytes = static_cast<double>(capacity) *
                       static_cast<double>(2 * observation_size + action_size + 2) * sizeof(float);
  const double memory =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  if (memory > 0.0 && bytes > memory) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "a replay buffer of %lld transitions needs %.1f GiB, more than this machine's "
                  "%.1f GiB of memory",
                  static_cast<long long>(capacity), bytes / (1 << 30), memory / (1 << 30));
    throw Error(text, "algo.buffer_size");
  }
  // Uninitialised: the pages are committed as transitions are written.
  observations_.resize(observation_size, capacity);
  next_observations_.resize(observation_size, capacity);
  actions_.resize(action_size, capacity);
  rewards_.resize(capacity);
  terminated_.resize(capacity);
}

void ReplayBuffer::add(const Eigen::Ref<const Eigen::VectorXf>& observation,
                       const Eigen::Ref<const Eigen::VectorXf>& action, float reward,
                       const Eigen::Ref<const Eigen::VectorXf>& next_observation, bool terminated) {
  observations_.col(position_) = observation;
  actions_.col(position_) = action;
  rewards_[position_] = reward;
  next_observations_.col(position_) = next_observation;
  terminated_[position_] = terminated ? 1.0f : 0.0f;
  position_ = (position_ + 1) % capacity_;
  if (size_ < capacity_) ++size_;
}

void ReplayBuffer::sample(int64_t batch_size, Rng& rng, Batch& batch) const {
  require(size_ > 0, "cannot sample from an empty replay buffer", "rl::ReplayBuffer::sample");
  batch.observations.resize(observations_.rows(), batch_size);
  batch.next_observations.resize(observations_.rows(), batch_size);
  batch.actions.resize(actions_.rows(), batch_size);
  batch.rewards.resize(batch_size);
  batch.terminated.resize(batch_size);
  for (int64_t i = 0; i < batch_size; ++i) {
    const auto index = static_cast<Eigen::Index>(rng.below(static_cast<uint64_t>(size_)));
    batch.observations.col(i) = observations_.col(index);
    batch.next_observations.col(i) = next_observations_.col(index);
    batch.actions.col(i) = actions_.col(index);
    batch.rewards[i] = rewards_[index];
    batch.terminated[i] = terminated_[index];
  }
}

uint32_t ReplayBuffer::save(const std::filesystem::path& file) const {
  const std::string bytes = serialize();
  write_file_atomically(file, bytes, "replay buffer");
  uint32_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + bytes.size() - sizeof checksum, sizeof checksum);
  return checksum;
}

std::string ReplayBuffer::serialize() const {
  std::string bytes(kMagic, sizeof kMagic);
  const int64_t header[kHeaderWords] = {kFormat,       capacity_, observation_size(),
                                        action_size(), size_,     position_};
  bytes.append(reinterpret_cast<const char*>(header), sizeof header);
  append_columns(bytes, observations_, size_);
  append_columns(bytes, actions_, size_);
  bytes.append(reinterpret_cast<const char*>(rewards_.data()),
               static_cast<std::size_t>(size_) * sizeof(float));
  append_columns(bytes, next_observations_, size_);
  bytes.append(reinterpret_cast<const char*>(terminated_.data()),
               static_cast<std::size_t>(size_) * sizeof(float));
  const uint32_t checksum = crc32c(bytes.data() + sizeof kMagic, bytes.size() - sizeof kMagic);
  bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  return bytes;
}

uint32_t replay_buffer_checksum(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary | std::ios::ate);
  require(stream.good(), "cannot open replay buffer file", file.string());
  const std::streamoff bytes = stream.tellg();
  require(bytes >= static_cast<std::streamoff>(sizeof kMagic + kHeaderWords * sizeof(int64_t) +
                                               sizeof(uint32_t)),
          "not a replay buffer file (or truncated)", file.string());
  uint32_t stored = 0;
  stream.seekg(bytes - static_cast<std::streamoff>(sizeof stored));
  stream.read(reinterpret_cast<char*>(&stored), sizeof stored);
  require(stream.good(), "cannot read replay buffer file", file.string());
  return stored;
}

void ReplayBuffer::load(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::ifstream stream(file, std::ios::binary);
  require(stream.good(), "cannot open replay buffer file", where);
  // Never read more than a full buffer of this shape can take (a damaged or foreign file).
  std::error_code error;
  const uintmax_t file_bytes = std::filesystem::file_size(file, error);
  const double largest = static_cast<double>(kHeaderWords + 2) * sizeof(int64_t) +
                         static_cast<double>(capacity_) *
                             static_cast<double>(2 * observation_size() + action_size() + 2) *
                             sizeof(float);
  require(!error && static_cast<double>(file_bytes) <= largest,
          "replay buffer file is larger than a buffer of this capacity", where);
  load_bytes(
      std::string((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>()),
      where);
}

void ReplayBuffer::load_bytes(const std::string& bytes, const std::string& where) {
  const std::size_t header_bytes = sizeof kMagic + kHeaderWords * sizeof(int64_t);
  require(bytes.size() >= header_bytes + sizeof(uint32_t) &&
              std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0,
          "not a replay buffer file (or truncated)", where);
  int64_t header[kHeaderWords];
  std::memcpy(header, bytes.data() + sizeof kMagic, sizeof header);
  require(header[0] == kFormat, "unsupported replay buffer format " + std::to_string(header[0]),
          where);
  require(header[1] == capacity_ && header[2] == observation_size() && header[3] == action_size(),
          "replay buffer of capacity " + std::to_string(header[1]) + " with observation size " +
              std::to_string(header[2]) + " and action size " + std::to_string(header[3]) +
              " does not fit this one (" + std::to_string(capacity_) + ", " +
              std::to_string(observation_size()) + ", " + std::to_string(action_size()) + ")",
          where);
  const int64_t size = header[4];
  const int64_t position = header[5];
  require(size >= 0 && size <= capacity_ && position >= 0 && position < capacity_ &&
              (size == capacity_ || position == size),
          "replay buffer header is inconsistent", where);
  const auto floats_per_transition = 2 * observation_size() + action_size() + 2;
  const std::size_t expected =
      header_bytes + static_cast<std::size_t>(size * floats_per_transition) * sizeof(float) +
      sizeof(uint32_t);
  require(bytes.size() == expected, "replay buffer file is truncated or has trailing bytes", where);
  uint32_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
  require(
      crc32c(bytes.data() + sizeof kMagic, bytes.size() - sizeof kMagic - sizeof stored) == stored,
      "replay buffer file is corrupt (checksum mismatch)", where);

  // Everything checked: only now is this buffer changed.
  const char* cursor = bytes.data() + header_bytes;
  read_columns(cursor, observations_, size);
  read_columns(cursor, actions_, size);
  std::memcpy(rewards_.data(), cursor, static_cast<std::size_t>(size) * sizeof(float));
  cursor += static_cast<std::size_t>(size) * sizeof(float);
  read_columns(cursor, next_observations_, size);
  std::memcpy(terminated_.data(), cursor, static_cast<std::size_t>(size) * sizeof(float));
  size_ = size;
  position_ = position;
}

}  // namespace tendril::rl
