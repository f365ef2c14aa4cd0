// Fuzzing the checkpoint and model readers past their checksum: files mutated at random and
// given a valid CRC again (as a crafted file would be) must load or raise tendril::Error —
// never crash, hang or throw anything else — and a failed load leaves the algorithm usable.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Mutations (by `kind`) a hostile or damaged file shows: flipped bits, random bytes, a cut, a run
// of bytes copied elsewhere (lengths and counts changed together); then the CRC-32C is fixed.
std::string mutate(std::string bytes, Rng& rng, uint64_t kind) {
  const std::size_t body = bytes.size() - 4;
  const auto at = [&] { return static_cast<std::size_t>(rng.below(body)); };
  if (kind == 0) {
    for (uint64_t i = 0, n = 1 + rng.below(8); i < n; ++i)
      bytes[at()] ^= static_cast<char>(1 << rng.below(8));
  } else if (kind == 1) {
    for (uint64_t i = 0, n = 1 + rng.below(16); i < n; ++i)
      bytes[at()] = static_cast<char>(rng.below(256));
  } else if (kind == 2) {
    bytes.resize(at() + 4);
  } else {
    const std::size_t from = at(), to = at(),
                      length = std::min<std::size_t>(1 + rng.below(64), body - std::max(from, to));
    std::memmove(bytes.data() + to, bytes.data() + from, length);
  }
  const std::size_t checked = bytes.size() - 4;
  const uint32_t crc = crc32c(bytes.data(), checked);
  std::memcpy(bytes.data() + checked, &crc, 4);
  return bytes;
}

constexpr const char* kExperiment = R"(
algorithm: %s
env: {id: Pendulum-v1, n_envs: 2, normalize_observation: true}
algo: {%s}
n_timesteps: 1024
seed: 1
eval: {freq: 0}
checkpoint_freq: 512
)";

class CheckpointFuzz : public ::testing::TestWithParam<const char*> {};

TEST_P(CheckpointFuzz, MutatedFilesLoadOrRaiseError) {
  const std::string algorithm = GetParam();
  char yaml[512];
  std::snprintf(yaml, sizeof yaml, kExperiment, algorithm.c_str(),
                algorithm == "ppo" ? "n_steps: 128, batch_size: 64, n_epochs: 1"
                                   : "learning_starts: 100, batch_size: 16, net_arch: [16, 16]");
  const Experiment experiment = Experiment::from_config(Config::parse(yaml, "fuzz.yaml"));
  const fs::path run =
      fs::temp_directory_path() / ("tendril_fuzz_" + algorithm + "_" + std::to_string(::getpid()));
  fs::remove_all(run);
  train(experiment, run, {.stop_at = 512, .quiet = true});
  const fs::path checkpoint = latest_checkpoint(run);
  const std::string original = read_text(checkpoint);
  std::unique_ptr<envs::VecEnv> env = make_vec_env(experiment.env);
  std::unique_ptr<Algorithm> learner = make_algorithm(experiment, *env);
  learner->save_policy(run / "model.policy");
  const std::string model = read_text(run / "model.policy");

  Rng rng(20261123, algorithm.size());
  const fs::path mutated = run / "mutated.ckpt", mutated_model = run / "mutated.policy";
  learner->load(checkpoint);
  const int64_t steps = learner->num_timesteps();
  // Counts by kind of mutation; anything but tendril::Error escapes and fails the test.
  int refused[4] = {}, loaded[4] = {};
  for (int trial = 0; trial < 300; ++trial) {
    const uint64_t kind = rng.below(4);
    std::ofstream(mutated, std::ios::binary | std::ios::trunc) << mutate(original, rng, kind);
    try {
      learner->load(mutated);
      ++loaded[kind];
    } catch (const Error&) {
      ++refused[kind];
    }
    std::ofstream(mutated_model, std::ios::binary | std::ios::trunc) << mutate(model, rng, kind);
    try {
      load_policy(mutated_model);
      ++loaded[kind];
    } catch (const Error&) {
      ++refused[kind];
    }
  }
  // A cut file (its count of entries no longer matches) is always refused; changed weights
  // under a recomputed CRC are numbers like any other and may load.
  EXPECT_EQ(loaded[2], 0);
  EXPECT_GT(refused[2], 0);
  EXPECT_GT(refused[0] + refused[1] + refused[3], 0);
  // The algorithm still loads the intact checkpoint.
  learner->load(checkpoint);
  EXPECT_EQ(learner->num_timesteps(), steps);
  fs::remove_all(run);
}

INSTANTIATE_TEST_SUITE_P(Algorithms, CheckpointFuzz, ::testing::Values("ppo", "sac"));

}  // namespace
}  // namespace tendril::rl
