#pragma once

#include <cstddef>
#include <cstdint>

namespace tendril {

// CRC-32C (Castagnoli polynomial 0x1EDC6F41, reflected 0x82F63B78), as used by TFRecord files.
uint32_t crc32c(const void* data, std::size_t size);

}  // namespace tendril
