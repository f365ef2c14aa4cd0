// libFuzzer target: replay-buffer files (rl/replay_buffer, saved beside a run's checkpoints),
// loaded into buffers of two shapes and sampled from. Bad input must raise tendril::Error and
// leave the buffer as it was.
#include <cstddef>
#include <cstdint>

#include "fuzz_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/replay_buffer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = tendril::fuzzing::write_file("buffer.bin", data, size);
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
  return 0;
}
