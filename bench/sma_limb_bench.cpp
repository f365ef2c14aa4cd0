// Robot time per second of computation for the SMA limb twin behind SmaLimb/Robot-v0, driven by
// count-based exploration as in data collection. The baseline is real time: the ratio is robot
// seconds per CPU second (one core) and per wall second. Requirement: ≥ 200× (the thesis' 130
// min stiff data set in under 40 s). In the same run, the same twin at the step its rod needs
// without scaled rotary inertia (RodSpec::rotary_inertia_scale = 1, Δt = 0.1 ms) shows what the
// chosen resolution buys.
//
//   build-lite/bench/sma_limb_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/sma_limb/throttle_sources.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

namespace tendril::envs::sma_limb {
namespace {

void run(benchmark::State& state, physics::SmaLimbSpec spec) {
  LimbCalibration calibration = LimbCalibration::nominal(spec.name);
  calibration.zero_offset_deg = spec.sensor.zero_offset;
  SmaLimbEnv env(std::make_unique<TwinLimbRobot>(spec), calibration, 0);
  CountBasedExploration exploration;
  Rng rng(1);
  Observation observation = env.reset(1);
  Action action(2);
  double robot_s = 0.0;
  const std::clock_t cpu_start = std::clock();
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    // One hold: ten readings under the same throttles.
    const Eigen::Vector2d angles = observation.head<2>().cast<double>();
    const Eigen::Vector2i u = exploration.next(angles, rng);
    action << static_cast<float>(u.x()), static_cast<float>(u.y());
    for (int k = 0; k < 10; ++k) {
      const Step step = env.step(action);
      observation = step.observation;
      exploration.observe(observation.head<2>().cast<double>());
      robot_s = *step.info.get("time_s");
    }
  }
  const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  state.counters["robot_s"] = robot_s;
  state.counters["realtime_x_cpu"] = robot_s / cpu_s;
  state.counters["realtime_x_wall"] = robot_s / wall_s;
  state.counters["min_130_cpu_s"] = 7800.0 / (robot_s / cpu_s);  // the stiff data set
}

void BM_StiffTwinExploring(benchmark::State& state) { run(state, physics::SmaLimbSpec::stiff()); }
void BM_SoftTwinExploring(benchmark::State& state) { run(state, physics::SmaLimbSpec::soft()); }
void BM_StiffTwinUnscaledInertia(benchmark::State& state) {
  physics::SmaLimbSpec spec = physics::SmaLimbSpec::stiff();
  spec.rotary_inertia_scale = 1.0;
  spec.steps_per_millisecond = 10;  // the stable step without the scaled inertia
  run(state, spec);
}

BENCHMARK(BM_StiffTwinExploring)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_SoftTwinExploring)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_StiffTwinUnscaledInertia)->Unit(benchmark::kMillisecond)->MinTime(5.0);

}  // namespace
}  // namespace tendril::envs::sma_limb

BENCHMARK_MAIN();
