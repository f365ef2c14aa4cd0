#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace tendril {

// CRC-32C (Castagnoli polynomial 0x1EDC6F41, reflected 0x82F63B78), as used by TFRecord files.
uint32_t crc32c(const void* data, std::size_t size);

// CRC-32 (IEEE 802.3 polynomial 0x04C11DB7, reflected 0xEDB88320), as used by zlib, PNG and
// Python's zlib.crc32: the check of recorded episode files, which readers outside tendril verify.
uint32_t crc32(const void* data, std::size_t size);

// A checksum as 8 lower-case hex digits.
std::string checksum_text(uint32_t checksum);

}  // namespace tendril
