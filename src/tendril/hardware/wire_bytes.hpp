#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::hardware {

// Little-endian field writer and reader for message payloads. The reader raises Error naming
// the message when the payload is shorter than its fields or has bytes left over.
class WireWriter {
 public:
  void u8(uint8_t value) { bytes_.push_back(value); }
  void u16(uint16_t value) { put(value, 2); }
  void u32(uint32_t value) { put(value, 4); }
  void u64(uint64_t value) { put(value, 8); }
  void i16(int16_t value) { u16(static_cast<uint16_t>(value)); }
  void i32(int32_t value) { u32(static_cast<uint32_t>(value)); }
  void f64(double value) { u64(std::bit_cast<uint64_t>(value)); }
  void text(const std::string& value) {
    require(value.size() <= 255, "text field longer than 255 bytes", "wire");
    u8(static_cast<uint8_t>(value.size()));
    bytes_.insert(bytes_.end(), value.begin(), value.end());
  }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  void put(uint64_t value, int count) {
    for (int i = 0; i < count; ++i) bytes_.push_back(static_cast<uint8_t>(value >> (8 * i)));
  }
  std::vector<uint8_t> bytes_;
};

class WireReader {
 public:
  WireReader(std::span<const uint8_t> bytes, const char* message)
      : bytes_(bytes), message_(message) {}
  uint8_t u8() { return static_cast<uint8_t>(get(1)); }
  uint16_t u16() { return static_cast<uint16_t>(get(2)); }
  uint32_t u32() { return static_cast<uint32_t>(get(4)); }
  uint64_t u64() { return get(8); }
  int16_t i16() { return static_cast<int16_t>(u16()); }
  int32_t i32() { return static_cast<int32_t>(u32()); }
  double f64() { return std::bit_cast<double>(u64()); }
  std::string text() {
    const size_t length = u8();
    need(length);
    std::string value(reinterpret_cast<const char*>(bytes_.data() + at_), length);
    at_ += length;
    return value;
  }
  void finish() const {
    if (at_ != bytes_.size()) {
      throw Error(std::string(message_) + " payload has " + std::to_string(bytes_.size() - at_) +
                      " bytes past its fields",
                  "wire");
    }
  }

 private:
  void need(size_t count) const {
    if (bytes_.size() - at_ < count) {
      throw Error(std::string(message_) + " payload of " + std::to_string(bytes_.size()) +
                      " bytes is too short for its fields",
                  "wire");
    }
  }
  uint64_t get(int count) {
    need(static_cast<size_t>(count));
    uint64_t value = 0;
    for (int i = 0; i < count; ++i) value |= static_cast<uint64_t>(bytes_[at_ + i]) << (8 * i);
    at_ += static_cast<size_t>(count);
    return value;
  }
  std::span<const uint8_t> bytes_;
  const char* message_;
  size_t at_ = 0;
};

}  // namespace tendril::hardware
