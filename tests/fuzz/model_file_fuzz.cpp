// libFuzzer target: the learned dynamics model file (`model.tdm`, dynamics/model_file_format),
// read through its torch-free decoder. Each input is read as it is and with its checksum line
// made right, so that the header, the parameter table and the payload behind the check are
// reached. Bad input must raise tendril::Error, and no header may make the reader allocate more
// than the input holds (libFuzzer's -rss_limit_mb catches that).
#include <cstddef>
#include <cstdint>
#include <string>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model_file_format.hpp"

namespace {

void decode(const std::string& bytes) {
  try {
    (void)tendril::dynamics::decode_model_file(bytes, "fuzz.tdm");
  } catch (const tendril::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  decode(bytes);
  const std::size_t line = bytes.rfind("crc32c ");
  if (line != std::string::npos) {
    std::string resealed = bytes.substr(0, line);
    resealed += "crc32c " + tendril::checksum_text(tendril::crc32c(resealed.data(), line)) + "\n";
    decode(resealed);
  }
  return 0;
}
