#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>

#include "tendril/hardware/frame.hpp"

namespace tendril::hardware {

// Turns a byte stream into frames. Anything may arrive: bytes before a sync pair are skipped,
// a frame of another version, an over-long length or a wrong checksum is counted and dropped,
// and the search for the next sync pair restarts at the byte after the bad frame's sync (so a
// frame that began inside the rejected bytes is still found). Never allocates beyond one frame.
class FrameParser {
 public:
  struct Counters {
    uint64_t frames = 0;  // accepted
    uint64_t checksum_errors = 0;
    uint64_t version_errors = 0;
    uint64_t length_errors = 0;
    uint64_t skipped_bytes = 0;  // outside any accepted frame
  };

  // Feeds bytes; the frames they completed wait in arrival order for next().
  void push(uint8_t byte);
  void push(std::span<const uint8_t> bytes);
  std::optional<Frame> next();
  const Counters& counters() const { return counters_; }
  uint64_t errors() const {
    return counters_.checksum_errors + counters_.version_errors + counters_.length_errors;
  }
  void clear();  // forgets a partial frame

 private:
  void reject();

  // The bytes of the frame being read, from its sync pair on.
  std::array<uint8_t, Frame::kMaxBytes> buffer_{};
  int size_ = 0;
  Counters counters_;
  std::deque<Frame> ready_;
};

}  // namespace tendril::hardware
