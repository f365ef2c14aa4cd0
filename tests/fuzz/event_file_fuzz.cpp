// libFuzzer target: the TensorBoard event-file reader (read_event_scalars, core/scalar_log).
// The first input byte picks the mode: even — the rest is the file as it is (framing, lengths,
// CRCs); odd — the rest is cut at each 0xff 0xfe pair into record payloads that the harness
// frames with correct lengths and CRCs, so that the protobuf parsing behind the checksums is
// reached. Bad input must raise tendril::Error.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/scalar_log.hpp"

namespace {

// TFRecord's masked CRC-32C.
uint32_t masked_crc(const void* data, size_t size) {
  const uint32_t crc = tendril::crc32c(data, size);
  return ((crc >> 15) | (crc << 17)) + 0xA282EAD8u;
}

void append_record(std::string& out, const std::string& payload) {
  const uint64_t length = payload.size();
  const uint32_t length_crc = masked_crc(&length, sizeof length);
  const uint32_t data_crc = masked_crc(payload.data(), payload.size());
  out.append(reinterpret_cast<const char*>(&length), sizeof length);
  out.append(reinterpret_cast<const char*>(&length_crc), sizeof length_crc);
  out += payload;
  out.append(reinterpret_cast<const char*>(&data_crc), sizeof data_crc);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::string file_bytes;
  if (data[0] % 2 == 0) {
    file_bytes = rest;
  } else {
    size_t start = 0;
    while (true) {
      const size_t cut = rest.find("\xff\xfe", start);
      append_record(file_bytes, rest.substr(start, cut == std::string::npos ? cut : cut - start));
      if (cut == std::string::npos) break;
      start = cut + 2;
    }
  }
  const auto file = tendril::fuzzing::write_file("events", file_bytes.data(), file_bytes.size());
  try {
    (void)tendril::read_event_scalars(file);
  } catch (const tendril::Error&) {
  }
  return 0;
}
