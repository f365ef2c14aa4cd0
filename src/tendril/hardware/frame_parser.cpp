#include "tendril/hardware/frame_parser.hpp"

#include <algorithm>

namespace tendril::hardware {

void FrameParser::clear() {
  counters_.skipped_bytes += size_;
  size_ = 0;
}

void FrameParser::reject() {
  // Rescan what followed the bad frame's first sync byte: a good frame may start inside it.
  const int held = size_;
  std::array<uint8_t, Frame::kMaxBytes> rest;
  std::copy(buffer_.begin() + 1, buffer_.begin() + held, rest.begin());
  size_ = 0;
  counters_.skipped_bytes += 1;
  for (int i = 0; i < held - 1; ++i) push(rest[i]);
}

void FrameParser::push(std::span<const uint8_t> bytes) {
  for (const uint8_t byte : bytes) push(byte);
}

std::optional<Frame> FrameParser::next() {
  if (ready_.empty()) return std::nullopt;
  Frame frame = std::move(ready_.front());
  ready_.pop_front();
  return frame;
}

void FrameParser::push(uint8_t byte) {
  if (size_ == 0) {
    if (byte == Frame::kSync0) {
      buffer_[size_++] = byte;
    } else {
      ++counters_.skipped_bytes;
    }
    return;
  }
  if (size_ == 1) {
    if (byte == Frame::kSync1) {
      buffer_[size_++] = byte;
    } else {
      ++counters_.skipped_bytes;
      if (byte != Frame::kSync0) size_ = 0;  // A5 A5 5A: the second A5 may start the frame
    }
    return;
  }
  buffer_[size_++] = byte;
  if (size_ == 3 && byte != Frame::kVersion) {
    ++counters_.version_errors;
    reject();
    return;
  }
  if (size_ < Frame::kHeaderBytes) return;
  const int length = buffer_[Frame::kHeaderBytes - 2];
  if (size_ == Frame::kHeaderBytes &&
      crc8(std::span(buffer_).subspan(2, Frame::kHeaderBytes - 3)) != byte) {
    ++counters_.checksum_errors;
    reject();
    return;
  }
  if (length > Frame::kMaxPayload) {
    ++counters_.length_errors;
    reject();
    return;
  }
  const int total = Frame::kHeaderBytes + length + 2;
  if (size_ < total) return;
  const uint16_t expected = crc16(std::span(buffer_).subspan(2, total - 4));
  const uint16_t got = static_cast<uint16_t>(buffer_[total - 2] | (buffer_[total - 1] << 8));
  if (got != expected) {
    ++counters_.checksum_errors;
    reject();
    return;
  }
  Frame frame;
  frame.type = buffer_[3];
  frame.seq = static_cast<uint16_t>(buffer_[4] | (buffer_[5] << 8));
  frame.stamp_ms = static_cast<uint32_t>(buffer_[6]) | (static_cast<uint32_t>(buffer_[7]) << 8) |
                   (static_cast<uint32_t>(buffer_[8]) << 16) |
                   (static_cast<uint32_t>(buffer_[9]) << 24);
  frame.payload.assign(buffer_.begin() + Frame::kHeaderBytes,
                       buffer_.begin() + Frame::kHeaderBytes + length);
  size_ = 0;
  ++counters_.frames;
  ready_.push_back(std::move(frame));
}

}  // namespace tendril::hardware
