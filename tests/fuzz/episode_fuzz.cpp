// libFuzzer target: recorded episode files (core/episode_reader, docs/episode_format.md), read
// whole and as a partial recording (a file still being written); each input as it is and with
// every record's checksum made right, so that the record decoding behind the checks is reached.
// Bad input must raise tendril::Error.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/episode_format.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"

namespace {

namespace fmt = tendril::episode_format;

// Records follow the magic: u8 tag, u32 length, payload, u32 zlib CRC-32 of tag, length and
// payload. Every whole record gets its right CRC.
std::string with_right_checksums(std::string bytes) {
  std::size_t position = fmt::kMagic.size();
  while (position + 5 <= bytes.size()) {
    uint32_t length;
    std::memcpy(&length, bytes.data() + position + 1, sizeof length);
    if (bytes.size() - position < fmt::kRecordOverhead + std::size_t{length}) break;
    const uint32_t crc = tendril::crc32(bytes.data() + position, 5 + std::size_t{length});
    std::memcpy(bytes.data() + position + 5 + length, &crc, sizeof crc);
    position += fmt::kRecordOverhead + length;
  }
  return bytes;
}

void read(const std::string& bytes) {
  const auto file = tendril::fuzzing::write_file("episode.tep", bytes.data(), bytes.size());
  try {
    (void)tendril::read_episode(file);
  } catch (const tendril::Error&) {
  }
  try {
    (void)tendril::read_partial_episode(file);
  } catch (const tendril::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read(bytes);
  const std::string sealed = with_right_checksums(bytes);
  if (sealed != bytes) read(sealed);
  return 0;
}
