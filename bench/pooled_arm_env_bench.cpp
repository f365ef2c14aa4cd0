// n_envs copies of Elastica/Tracking3D-v0 (case 1: 20 elements, dt 0.2 ms, 7 rod steps per
// action) on one core: the vector env whose rods advance together in one RodPool
// (lockstep_rods: true, PooledArmVecEnv) against the vector env of n_envs single envs on one
// thread (ThreadedVecEnv, what make_vec_env builds otherwise), in the same run. Both step the
// whole task: random actions, muscles, rods, target motion, observations, rewards, infos and
// the episode statistics.
//
//   build/bench/pooled_arm_env_bench [seconds per measurement, default 0.5]
//
// Prints env steps per second per core (the median of 5 interleaved measurements) for
// n_envs = 1, 4, 8 and 64 and the ratio pooled / separate.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs {
namespace {

using bench::Clock;
using bench::seconds_since;

constexpr const char* kId = "Elastica/Tracking3D-v0";
constexpr int kRepeats = 5;
constexpr int kActionSets = 16;  // drawn before timing and cycled

std::unique_ptr<VecEnv> separate(int n_envs) {
  return std::make_unique<ThreadedVecEnv>(
      n_envs, [](int) { return std::make_unique<EpisodeStatistics>(make(kId)); }, 1);
}

std::unique_ptr<VecEnv> pooled(int n_envs) {
  std::unique_ptr<VecEnv> env = make_vector(kId, Config::parse("lockstep_rods: true"), n_envs);
  if (!env) std::abort();
  return env;
}

// Env steps per second of `env` under random actions, after 0.14 s of simulated warm-up.
double rate(VecEnv& env, double seconds) {
  const int n = env.num_envs();
  Rng rng(3);
  std::vector<BatchMatrix> actions(kActionSets, BatchMatrix(n, env.action_space().size()));
  for (BatchMatrix& set : actions) {
    for (int i = 0; i < n; ++i) set.row(i) = env.action_space().sample(rng).transpose();
  }
  env.reset(0);
  for (int k = 0; k < 100; ++k) env.step(actions[k % kActionSets]);
  int64_t steps = 0;
  double sink = 0.0;
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    for (int k = 0; k < kActionSets; ++k) {
      sink += env.step(actions[k]).rewards[0];
      steps += n;
    }
  }
  const double elapsed = seconds_since(start);
  if (sink != sink) std::abort();  // keeps the rewards used; a NaN reward would be a bug
  return static_cast<double>(steps) / elapsed;
}

}  // namespace
}  // namespace tendril::envs

int main(int argc, char** argv) {
  using namespace tendril::envs;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.5;
  std::printf("%s, 20 elements, dt 0.2 ms, 7 rod steps per env step, one core\n", kId);
  std::printf("%7s  %22s  %22s  %8s  %13s\n", "n_envs", "separate env steps/s",
              "lockstep env steps/s", "ratio", "lockstep us");
  for (int n_envs : {1, 4, 8, 64}) {
    std::unique_ptr<VecEnv> a = separate(n_envs), b = pooled(n_envs);
    std::vector<double> separate_rates, pooled_rates;
    // Interleaved, so that a slower phase of the machine affects both alike.
    for (int repeat = 0; repeat < kRepeats; ++repeat) {
      separate_rates.push_back(rate(*a, seconds));
      pooled_rates.push_back(rate(*b, seconds));
    }
    const double s = tendril::bench::median(separate_rates);
    const double p = tendril::bench::median(pooled_rates);
    std::printf("%7d  %22.0f  %22.0f  %7.2fx  %13.3f\n", n_envs, s, p, p / s, 1e6 / p);
  }
  return 0;
}
