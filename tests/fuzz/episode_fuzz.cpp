// libFuzzer target: recorded episode files (core/episode_reader, docs/episode_format.md), read
// whole and as a partial recording (a file still being written). Bad input must raise
// tendril::Error.
#include <cstddef>
#include <cstdint>

#include "fuzz_file.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = tendril::fuzzing::write_file("episode.tep", data, size);
  try {
    (void)tendril::read_episode(file);
  } catch (const tendril::Error&) {
  }
  try {
    (void)tendril::read_partial_episode(file);
  } catch (const tendril::Error&) {
  }
  return 0;
}
