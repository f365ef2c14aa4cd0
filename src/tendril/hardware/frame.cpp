#include "tendril/hardware/frame.hpp"

#include "tendril/core/error.hpp"

namespace tendril::hardware {

uint16_t crc16(std::span<const uint8_t> bytes, uint16_t crc) {
  for (const uint8_t byte : bytes) {
    crc ^= static_cast<uint16_t>(byte << 8);
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x8000) ? static_cast<uint16_t>((crc << 1) ^ 0x1021)
                           : static_cast<uint16_t>(crc << 1);
    }
  }
  return crc;
}

uint8_t crc8(std::span<const uint8_t> bytes) {
  uint8_t crc = 0;
  for (const uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80) ? static_cast<uint8_t>((crc << 1) ^ 0x07) : static_cast<uint8_t>(crc << 1);
    }
  }
  return crc;
}

std::vector<uint8_t> Frame::encode() const {
  require(payload.size() <= kMaxPayload, "frame payload longer than 200 bytes", "Frame::encode");
  std::vector<uint8_t> bytes;
  bytes.reserve(kHeaderBytes + payload.size() + 2);
  bytes.insert(bytes.end(), {kSync0, kSync1, kVersion, type, static_cast<uint8_t>(seq),
                             static_cast<uint8_t>(seq >> 8)});
  for (int shift = 0; shift < 32; shift += 8)
    bytes.push_back(static_cast<uint8_t>(stamp_ms >> shift));
  bytes.push_back(static_cast<uint8_t>(payload.size()));
  bytes.push_back(crc8(std::span(bytes).subspan(2)));
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  const uint16_t crc = crc16(std::span(bytes).subspan(2));
  bytes.push_back(static_cast<uint8_t>(crc));
  bytes.push_back(static_cast<uint8_t>(crc >> 8));
  return bytes;
}

}  // namespace tendril::hardware
