// Many copies of the case-1 Elastica arm (20 elements, dt 0.2 ms) on one core: N rods stepped
// in lockstep by a RodPool against the same N rods stepped one after another as lone Rods, in
// the same run. Both run as the RL environments drive the arm: per action, new random muscle
// targets for every rod, then 7 steps (1.4 ms).
//
//   build/bench/rod_pool_bench [seconds per measurement, default 0.5]
//
// Prints rod steps per second per core (the median of 5 measurements) for N = 1, 8 and 64 and
// the ratio pool / lone.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/rod/rod_pool.hpp"

namespace tendril::physics {
namespace {

using bench::Clock;
using bench::median;
using bench::seconds_since;

constexpr int kSubsteps = 7;  // one RL action of the Elastica cases
constexpr int kRepeats = 5;

Eigen::VectorXd draw_targets(Rng& rng, int size) {
  Eigen::VectorXd targets(size);
  for (int k = 0; k < size; ++k) targets[k] = rng.uniform(-0.3, 0.3);
  return targets;
}

// Rod steps per second of `count` lone arms, each advanced one action in turn.
double lone_rate(int count, double seconds) {
  const ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  std::vector<ElasticaArm> arms;
  for (int r = 0; r < count; ++r) arms.push_back(build_elastica_arm(spec));
  Rng rng(1);
  const int size = spec.actuation.action_size();
  std::vector<Eigen::VectorXd> targets(count, Eigen::VectorXd(size));
  // Settle into bent, moving shapes first (0.2 s), as in an episode.
  for (int r = 0; r < count; ++r) {
    arms[r].muscles->set_targets(draw_targets(rng, size));
    if (!arms[r].rod.advance(1000)) std::abort();
  }
  int64_t steps = 0;
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    for (int repeat = 0; repeat < 10; ++repeat) {
      for (int r = 0; r < count; ++r) targets[r] = draw_targets(rng, size);
      for (int r = 0; r < count; ++r) {
        arms[r].muscles->set_targets(targets[r]);
        if (!arms[r].rod.advance(kSubsteps)) std::abort();
      }
      steps += static_cast<int64_t>(count) * kSubsteps;
    }
  }
  return static_cast<double>(steps) / seconds_since(start);
}

// Rod steps per second of `count` arms in one pool.
double pool_rate(int count, double seconds) {
  const ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  RodPool pool(build_elastica_arm(spec).rod, count);
  Rng rng(1);
  const int size = spec.actuation.action_size();
  std::vector<Eigen::VectorXd> targets(count, Eigen::VectorXd(size));
  for (int r = 0; r < count; ++r) pool.set_targets(r, draw_targets(rng, size));
  if (!pool.advance(1000)) std::abort();
  int64_t steps = 0;
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    for (int repeat = 0; repeat < 10; ++repeat) {
      for (int r = 0; r < count; ++r) targets[r] = draw_targets(rng, size);
      for (int r = 0; r < count; ++r) pool.set_targets(r, targets[r]);
      if (!pool.advance(kSubsteps)) std::abort();
      steps += static_cast<int64_t>(count) * kSubsteps;
    }
  }
  return static_cast<double>(steps) / seconds_since(start);
}

}  // namespace
}  // namespace tendril::physics

int main(int argc, char** argv) {
  using namespace tendril::physics;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.5;
  std::printf("case-1 Elastica arm, 20 elements, dt 0.2 ms, %d steps per action, one core\n",
              kSubsteps);
  std::printf("%5s  %20s  %20s  %8s  %14s\n", "N", "lone rods steps/s", "RodPool steps/s", "ratio",
              "pool us/step");
  for (int count : {1, 8, 64}) {
    std::vector<double> lone, pooled;
    // Interleaved, so that a slower phase of the machine affects both alike.
    for (int repeat = 0; repeat < kRepeats; ++repeat) {
      lone.push_back(lone_rate(count, seconds));
      pooled.push_back(pool_rate(count, seconds));
    }
    const double a = tendril::bench::median(lone), b = tendril::bench::median(pooled);
    std::printf("%5d  %20.0f  %20.0f  %7.2fx  %14.3f\n", count, a, b, b / a, 1e6 / b);
  }
  return 0;
}
