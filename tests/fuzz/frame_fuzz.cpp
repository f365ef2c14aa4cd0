// libFuzzer target: the wire protocol's parser (hardware/frame_parser) and every message
// decoder behind it — what a robot, a noisy cable or a stranger on the robot's UDP port can
// put on the wire. Nothing may crash; a bad payload raises tendril::Error; every frame the
// parser accepts re-encodes to bytes that parse back to the same frame, and feeding the same
// bytes in any split yields the same frames.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/hardware/frame_parser.hpp"
#include "tendril/hardware/messages.hpp"

namespace {

using namespace tendril::hardware;

template <typename Message>
void decode(const Frame& frame) {
  try {
    const Message message = Message::decode(frame.payload);
    // What decodes re-encodes to the same payload.
    if (message.encode() != frame.payload) std::abort();
  } catch (const tendril::Error&) {
  }
}

std::vector<Frame> parse_all(const uint8_t* data, size_t size, size_t chunk) {
  FrameParser parser;
  std::vector<Frame> frames;
  for (size_t at = 0; at < size; at += chunk) {
    const size_t n = std::min(chunk, size - at);
    parser.push(std::span<const uint8_t>(data + at, n));
    while (auto frame = parser.next()) frames.push_back(*frame);
  }
  return frames;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<Frame> frames = parse_all(data, size, size == 0 ? 1 : size);
  const std::vector<Frame> bytewise = parse_all(data, size, 1);
  if (frames.size() != bytewise.size()) std::abort();
  for (size_t i = 0; i < frames.size(); ++i) {
    const Frame& frame = frames[i];
    if (frame.encode() != bytewise[i].encode()) std::abort();
    FrameParser again;
    again.push(frame.encode());
    const auto back = again.next();
    if (!back || back->encode() != frame.encode()) std::abort();
    decode<Identity>(frame);
    decode<ResetRequest>(frame);
    decode<PwmCommand>(frame);
    decode<LimbReading>(frame);
    decode<Status>(frame);
    decode<Refused>(frame);
    decode<Pong>(frame);
    decode<CommandAck>(frame);
    decode<PressureCommand>(frame);
    decode<PressureReport>(frame);
    decode<MocapFrame>(frame);
    (void)message_name(frame.type);
  }
  return 0;
}
