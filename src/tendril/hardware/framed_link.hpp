#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tendril/hardware/frame_parser.hpp"
#include "tendril/hardware/messages.hpp"
#include "tendril/hardware/transport.hpp"

namespace tendril::hardware {

// Frames over a Transport: numbers and stamps what it sends (stamp: ms since the link was
// made), and hands out the frames that arrive.
class FramedLink {
 public:
  using Clock = std::chrono::steady_clock;

  explicit FramedLink(std::unique_ptr<Transport> transport);

  // Sends a frame; returns its sequence number. LinkDown if the link failed.
  uint16_t send(MessageType type, const std::vector<uint8_t>& payload = {});
  // The next frame, waiting for it until `deadline`; nullopt if none came. LinkDown if the
  // link failed.
  std::optional<Frame> next(Clock::time_point deadline);
  // Reopens the transport and forgets partial frames.
  void reopen();
  // Sends a PING and waits for its PONG: the round trip in seconds. Frames arriving meanwhile
  // go to `other`. LinkDown naming `who` if no PONG came within `timeout_s`.
  double ping(double timeout_s, const std::function<void(const Frame&)>& other,
              const std::string& who);

  const FrameParser& parser() const { return parser_; }
  Transport& transport() { return *transport_; }
  uint64_t frames_sent() const { return frames_sent_; }

 private:
  std::unique_ptr<Transport> transport_;
  FrameParser parser_;
  std::vector<uint8_t> buffer_;
  uint16_t next_seq_ = 0;
  uint64_t frames_sent_ = 0;
  Clock::time_point epoch_ = Clock::now();
};

}  // namespace tendril::hardware
