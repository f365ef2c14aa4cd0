// libFuzzer target: the checksummed archives a user's run holds (core/archive) — checkpoints
// (`checkpoints/step_N.ckpt`) and policies (`model.policy`, read whole by rl::load_policy).
// Every entry the archive lists is read as every type; a policy archive is also opened as a
// policy and asked to act. Bad input must raise tendril::Error.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_file.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/policy.hpp"

namespace {

template <typename Read>
void attempt(Read&& read) {
  try {
    read();
  } catch (const tendril::Error&) {
  }
}

void read_everything(const tendril::ArchiveReader& reader) {
  for (const std::string& key : reader.keys()) {
    attempt([&] { (void)reader.get_int(key); });
    attempt([&] { (void)reader.get_double(key); });
    attempt([&] { (void)reader.get_string(key); });
    attempt([&] { (void)reader.get_floats(key); });
    attempt([&] { (void)reader.get_floats(key, 4); });
    attempt([&] { (void)reader.get_doubles(key); });
    attempt([&] { (void)reader.get_bytes(key); });
    attempt([&] { (void)reader.get_rng(key); });
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  for (const char* kind : {"checkpoint", "policy"}) {
    attempt([&] { read_everything(tendril::ArchiveReader::from_bytes(bytes, kind, "fuzz")); });
  }
  const auto file = tendril::fuzzing::write_file("model.policy", data, size);
  attempt([&] {
    const auto policy = tendril::rl::load_policy(file);
    const tendril::Observation observation =
        tendril::Observation::Zero(policy->observation_space().size());
    tendril::Rng rng(1);
    (void)policy->act(observation, true, rng);
  });
  return 0;
}
