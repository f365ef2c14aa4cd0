// Environment steps per second of the Elastica soft-arm cases, one core, random actions.
//
//   build/bench/elastica_env_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Baseline: the same 20-element arm wrapped as a Gymnasium env with PyElastica does 5,260 env
// steps per second on this kind of machine (7 rod steps per action, 44 observations, 12
// actions). PyElastica is not packaged for Debian, so that figure cannot be re-measured here.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril {
namespace {

constexpr double kPyElasticaCase1EnvStepsPerSecond = 5260.0;

void run(benchmark::State& state, const std::string& id) {
  const std::unique_ptr<Env> env = envs::make(id);
  Rng rng(7);
  env->reset(0);
  int64_t steps = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    const Action action = env->action_space().sample(rng);
    const Step step = env->step(action);
    benchmark::DoNotOptimize(step.observation.data());
    if (step.terminated || step.truncated) env->reset();
    ++steps;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double steps_per_second = static_cast<double>(steps) / seconds;
  state.counters["env_steps_per_s"] = steps_per_second;
  if (id == "Elastica/Tracking3D-v0") {
    state.counters["speedup_vs_pyelastica"] = steps_per_second / kPyElasticaCase1EnvStepsPerSecond;
  }
}

void BM_Tracking3D(benchmark::State& state) { run(state, "Elastica/Tracking3D-v0"); }
void BM_StructuredObstacles(benchmark::State& state) { run(state, "Elastica/StructuredObstacles-v0"); }

BENCHMARK(BM_Tracking3D)->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK(BM_StructuredObstacles)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

}  // namespace
}  // namespace tendril

BENCHMARK_MAIN();
