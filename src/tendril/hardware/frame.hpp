#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace tendril::hardware {

// One message of the wire protocol, version 1 (docs/protocol.md):
//   A5 5A | version | type | seq (u16) | stamp_ms (u32) | length n | CRC-8 | payload (n) | CRC-16
// little-endian throughout. The CRC-8 (poly 0x07, init 0) covers version through length, so a
// corrupted length is caught before the receiver waits for its bytes; the CRC-16/CCITT-FALSE
// (poly 0x1021, init 0xFFFF) covers version through payload. A sender numbers its frames 0, 1, 2, …
// (wrapping at 65536) and stamps them with its own clock in milliseconds.
struct Frame {
  static constexpr uint8_t kSync0 = 0xA5;
  static constexpr uint8_t kSync1 = 0x5A;
  static constexpr uint8_t kVersion = 1;
  static constexpr int kHeaderBytes = 12;
  static constexpr int kMaxPayload = 200;
  static constexpr int kMaxBytes = kHeaderBytes + kMaxPayload + 2;

  uint8_t type = 0;
  uint16_t seq = 0;
  uint32_t stamp_ms = 0;
  std::vector<uint8_t> payload;

  // The frame's bytes; Error if the payload exceeds kMaxPayload.
  std::vector<uint8_t> encode() const;
};

// CRC-16/CCITT-FALSE of `bytes`, continuing from `crc`.
uint16_t crc16(std::span<const uint8_t> bytes, uint16_t crc = 0xFFFF);
// CRC-8 (polynomial 0x07, initial 0, the SMBus one) of `bytes`.
uint8_t crc8(std::span<const uint8_t> bytes);

}  // namespace tendril::hardware
