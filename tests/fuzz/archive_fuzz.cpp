// libFuzzer target: the checksummed archives a user's run holds (core/archive) — checkpoints
// (`checkpoints/step_N.ckpt`, loaded into a PPO learner as a resumed run does) and policies
// (`model.policy`, read whole by rl::load_policy). Every entry the archive lists is read as
// every type; a policy archive is also opened as a policy and asked to act. Each input is read
// as it is and with its checksum made right, so that what lies behind the check is reached.
// Bad input must raise tendril::Error.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "fuzz_file.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

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

// The learner that fuzz_write_seeds saved its checkpoint from (same env, network and sizes).
tendril::rl::Ppo& learner() {
  static const std::unique_ptr<tendril::envs::VecEnv> env = [] {
    tendril::rl::VecEnvOptions options;
    options.id = "Pendulum-v1";
    return tendril::rl::make_vec_env(options);
  }();
  static tendril::rl::Ppo ppo(*env,
                              tendril::rl::PpoConfig::from_config(tendril::Config::parse(
                                  "n_steps: 16\nbatch_size: 8\npolicy: {net_arch: [4]}\n")),
                              0);
  return ppo;
}

// The archive's last four bytes hold the CRC-32C of every byte before them.
std::string with_right_checksum(std::string bytes) {
  if (bytes.size() < sizeof(uint32_t)) return bytes;
  const std::size_t body = bytes.size() - sizeof(uint32_t);
  const uint32_t crc = tendril::crc32c(bytes.data(), body);
  std::memcpy(bytes.data() + body, &crc, sizeof crc);
  return bytes;
}

void read_archive(const std::string& bytes) {
  for (const char* kind : {"checkpoint", "policy"}) {
    attempt([&] { read_everything(tendril::ArchiveReader::from_bytes(bytes, kind, "fuzz")); });
  }
  const auto file = tendril::fuzzing::write_file("model.policy", bytes.data(), bytes.size());
  attempt([&] {
    const auto policy = tendril::rl::load_policy(file);
    const tendril::Observation observation =
        tendril::Observation::Zero(policy->observation_space().size());
    tendril::Rng rng(1);
    (void)policy->act(observation, true, rng);
  });
  attempt([&] { learner().load(file); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_archive(bytes);
  const std::string sealed = with_right_checksum(bytes);
  if (sealed != bytes) read_archive(sealed);
  return 0;
}
