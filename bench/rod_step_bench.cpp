// Cost of one Cosserat-rod time step for the Elastica RL arms, against PyElastica.
//
//   build/bench/rod_step_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// PyElastica's figures (reference measurements of the same rods on this kind of machine)
// cannot be re-measured here: PyElastica is not packaged for Debian.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tendril/core/rng.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"

namespace tendril::physics {
namespace {

constexpr double kPyElasticaCase1MicrosecondsPerStep = 24.2;  // 20 elements, dt 0.2 ms
constexpr double kPyElasticaCase3MicrosecondsPerStep = 32.4;  // 50 elements, dt 0.1 ms

// Control points drawn afresh for every action, as an exploring RL policy commands them.
void set_muscles(ElasticaArm& arm, Rng& rng, double bias) {
  Eigen::VectorXd targets(arm.muscles->spec().action_size());
  for (Eigen::Index k = 0; k < targets.size(); ++k) targets[k] = bias + rng.uniform(-0.3, 0.3);
  arm.muscles->set_targets(targets);
}

// `bias` bends the arm on average (case 3: into the wall of cylinders, so contacts are live).
void run(benchmark::State& state, ElasticaArmSpec spec, double pyelastica_us, double bias) {
  ElasticaArm arm = build_elastica_arm(spec);
  Rng rng(0);
  set_muscles(arm, rng, bias);
  if (!arm.rod.advance(static_cast<int>(0.4 / spec.time_step))) state.SkipWithError("arm blew up");
  int64_t steps = 0;
  int64_t contact_samples = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    // One action's worth of substeps per iteration, as in the RL environments (1.4 ms).
    const int substeps = static_cast<int>(std::lround(1.4e-3 / spec.time_step));
    if (!arm.rod.advance(substeps)) {
      state.SkipWithError("arm blew up");
      break;
    }
    steps += substeps;
    if (arm.contact != nullptr) contact_samples += arm.contact->contacts();
    set_muscles(arm, rng, bias);
  }
  const double elapsed_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  const double us_per_step = elapsed_us / static_cast<double>(std::max<int64_t>(steps, 1));
  state.counters["us_per_step"] = us_per_step;
  state.counters["pyelastica_us_per_step"] = pyelastica_us;
  state.counters["speedup"] = pyelastica_us / us_per_step;
  if (arm.contact != nullptr) {
    state.counters["contacts"] = static_cast<double>(contact_samples) / state.iterations();
  }
}

void BM_Case1Arm20Elements(benchmark::State& state) {
  run(state, ElasticaArmSpec::tracking(), kPyElasticaCase1MicrosecondsPerStep, 0.0);
}
void BM_Case3Arm50ElementsEightCylinders(benchmark::State& state) {
  run(state, ElasticaArmSpec::structured_obstacles(), kPyElasticaCase3MicrosecondsPerStep, 0.5);
}

BENCHMARK(BM_Case1Arm20Elements)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_Case3Arm50ElementsEightCylinders)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

}  // namespace
}  // namespace tendril::physics

BENCHMARK_MAIN();
