// The C++ side of bench/python_vec_step_bench.py: vector-env steps per second of N copies of a
// registered environment stepped from C++ (the same VecEnv tendril.make_vec steps from Python),
// with the same 64 cycled action batches.
//
//   vec_step_cpp <env id> <num envs> <num threads> <seconds>   → one JSON line
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/rl/vec_env_factory.hpp"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: vec_step_cpp <env id> <num envs> <num threads> <seconds>\n");
    return 2;
  }
  tendril::rl::VecEnvOptions options;
  options.id = argv[1];
  options.n_envs = std::stoi(argv[2]);
  options.num_threads = std::stoi(argv[3]);
  const double budget = std::stod(argv[4]);
  const auto env = tendril::rl::make_vec_env(options);
  tendril::Rng rng(0);
  std::vector<tendril::envs::BatchMatrix> batches(64);
  for (auto& batch : batches) {
    batch.resize(options.n_envs, env->action_space().size());
    for (int i = 0; i < options.n_envs; ++i) {
      batch.row(i) = env->action_space().sample(rng).transpose();
    }
  }
  env->reset(0);
  for (int i = 0; i < 256; ++i) env->step(batches[i % 64]);  // warm-up
  long long steps = 0;
  const auto start = std::chrono::steady_clock::now();
  double seconds = 0.0;
  while (seconds < budget) {
    for (int i = 0; i < 256; ++i) env->step(batches[(steps + i) % 64]);
    steps += 256;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::printf("{\"vec_steps_per_s\": %.1f, \"steps\": %lld, \"seconds\": %.3f}\n",
              static_cast<double>(steps) / seconds, steps, seconds);
  return 0;
}
