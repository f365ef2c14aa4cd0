// libFuzzer target: replay-buffer files (rl/replay_buffer, saved beside a run's checkpoints),
// loaded into buffers of two shapes and sampled from; each input as it is and with its checksum
// made right. Bad input must raise tendril::Error and leave the buffer as it was.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <tuple>

#include "fuzz_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace {

// After the 8-byte magic, everything but the last four bytes is covered by the CRC-32C that
// those four bytes hold.
std::string with_right_checksum(std::string bytes) {
  constexpr std::size_t kMagic = 8;
  if (bytes.size() < kMagic + sizeof(uint32_t)) return bytes;
  const std::size_t body = bytes.size() - sizeof(uint32_t);
  const uint32_t crc = tendril::crc32c(bytes.data() + kMagic, body - kMagic);
  std::memcpy(bytes.data() + body, &crc, sizeof crc);
  return bytes;
}

void load(const std::string& bytes) {
  const auto file = tendril::fuzzing::write_file("buffer.bin", bytes.data(), bytes.size());
  for (const auto& [capacity, observations, actions] :
       {std::tuple<int64_t, int64_t, int64_t>{64, 3, 1}, {16, 4, 2}}) {
    tendril::rl::ReplayBuffer buffer(capacity, observations, actions);
    try {
      buffer.load(file);
    } catch (const tendril::Error&) {
    }
    if (buffer.size() > 0) {
      tendril::Rng rng(1);
      tendril::rl::ReplayBuffer::Batch batch;
      buffer.sample(8, rng, batch);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  load(bytes);
  const std::string sealed = with_right_checksum(bytes);
  if (sealed != bytes) load(sealed);
  return 0;
}
