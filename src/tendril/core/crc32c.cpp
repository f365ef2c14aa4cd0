#include "tendril/core/crc32c.hpp"

#include <array>
#include <cstdio>

namespace tendril {

namespace {

// The byte table of a reflected CRC with polynomial `reflected_polynomial`.
std::array<uint32_t, 256> make_table(uint32_t reflected_polynomial) {
  std::array<uint32_t, 256> table{};
  for (uint32_t byte = 0; byte < 256; ++byte) {
    uint32_t crc = byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (reflected_polynomial & (0u - (crc & 1u)));
    table[byte] = crc;
  }
  return table;
}

uint32_t reflected_crc(const std::array<uint32_t, 256>& table, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) crc = (crc >> 8) ^ table[(crc ^ bytes[i]) & 0xFFu];
  return crc ^ 0xFFFFFFFFu;
}

}  // namespace

uint32_t crc32c(const void* data, std::size_t size) {
  static const std::array<uint32_t, 256> table = make_table(0x82F63B78u);
  return reflected_crc(table, data, size);
}

uint32_t crc32(const void* data, std::size_t size) {
  static const std::array<uint32_t, 256> table = make_table(0xEDB88320u);
  return reflected_crc(table, data, size);
}

std::string checksum_text(uint32_t checksum) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08x", checksum);
  return hex;
}

}  // namespace tendril
