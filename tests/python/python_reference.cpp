// What the Python package's tests compare against, computed by the C++ API directly:
//   python_reference episode <env id> <seed> <actions file> <out file>
//     reset(seed), then one step per row of the actions (raw float32, action size per row);
//     writes the reset observation, then per step the observation, the reward (float64) and
//     terminated, truncated (one byte each), all raw little-endian.
//   python_reference act <policy file> <observations file> <deterministic 0|1> <seed> <out file>
//     rl::load_policy(file).act on each row (raw float32 observations), one Rng(seed) for all;
//     writes the actions (raw float32).
//   python_reference sample-policies <directory>
//     writes one policy file of every exportable kind and shape, <name>.policy
//     (tests/rl/export/sample_policies.hpp), for the export tests.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "rl/export/sample_policies.hpp"
#include "support/required_env_params.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/policy.hpp"

namespace {

std::vector<float> read_floats(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  tendril::require(static_cast<bool>(in), "cannot read", file);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
  tendril::require(bytes.size() % sizeof(float) == 0, "not a float32 array", file);
  std::vector<float> values(bytes.size() / sizeof(float));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(values.data()));
  return values;
}

template <typename T>
void put(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

void put(std::ofstream& out, const Eigen::VectorXf& values) {
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(float)));
}

int episode(const std::string& id, uint64_t seed, const std::string& actions_file,
            const std::string& out_file) {
  auto env = tendril::envs::make(id, tendril::testing::required_env_params(id));
  const std::vector<float> actions = read_floats(actions_file);
  const int size = env->action_space().size();
  std::ofstream out(out_file, std::ios::binary);
  put(out, env->reset(seed));
  for (std::size_t row = 0; row * size < actions.size(); ++row) {
    const tendril::Action action =
        Eigen::Map<const Eigen::VectorXf>(actions.data() + row * size, size);
    const tendril::Step step = env->step(action);
    put(out, step.observation);
    put(out, step.reward);
    put(out, static_cast<uint8_t>(step.terminated));
    put(out, static_cast<uint8_t>(step.truncated));
  }
  return 0;
}

int act(const std::string& policy_file, const std::string& observations_file, bool deterministic,
        uint64_t seed, const std::string& out_file) {
  const auto policy = tendril::rl::load_policy(policy_file);
  const std::vector<float> observations = read_floats(observations_file);
  const int size = policy->observation_space().size();
  tendril::Rng rng(seed);
  std::ofstream out(out_file, std::ios::binary);
  for (std::size_t row = 0; row * size < observations.size(); ++row) {
    const tendril::Observation observation =
        Eigen::Map<const Eigen::VectorXf>(observations.data() + row * size, size);
    put(out, policy->act(observation, deterministic, rng));
  }
  return 0;
}

int sample_policies(const std::string& directory) {
  for (const auto& [name, policy] : tendril::testing::sample_policies()) {
    policy->save(std::filesystem::path(directory) / (name + ".policy"));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 5 && args[0] == "episode") {
      return episode(args[1], std::stoull(args[2]), args[3], args[4]);
    }
    if (args.size() == 6 && args[0] == "act") {
      return act(args[1], args[2], args[3] == "1", std::stoull(args[4]), args[5]);
    }
    if (args.size() == 2 && args[0] == "sample-policies") return sample_policies(args[1]);
  } catch (const std::exception& error) {
    std::cerr << "python_reference: " << error.what() << "\n";
    return 1;
  }
  std::cerr << "usage: python_reference episode <id> <seed> <actions> <out>\n"
               "       python_reference act <policy> <observations> <0|1> <seed> <out>\n"
               "       python_reference sample-policies <directory>\n";
  return 2;
}
