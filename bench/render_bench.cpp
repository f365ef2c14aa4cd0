// Pictures per second of the software rasterizer (render/) on the Elastica case-1 arm mid-episode,
// against the environment's own step measured in the same run: `steps_per_picture` says how many
// environment steps one picture costs.
//
//   build/bench/render_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <chrono>

#include "bench_timing.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/render/scene_rasterizer.hpp"

namespace tendril {
namespace {

// Seconds per step of the environment (the same-run baseline), over `steps` random steps.
double seconds_per_step(Env& env, Rng& rng, int steps) {
  const auto start = bench::Clock::now();
  for (int i = 0; i < steps; ++i) {
    const Step step = env.step(env.action_space().sample(rng));
    if (step.terminated || step.truncated) env.reset();
  }
  return bench::seconds_since(start) / steps;
}

void BM_Picture(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0)), height = width * 3 / 4;
  const int supersample = static_cast<int>(state.range(1));
  const std::unique_ptr<Env> env = envs::make("Elastica/Tracking3D-v0");
  Rng rng(3);
  env->reset(0);
  const double step_seconds = seconds_per_step(*env, rng, 2000);
  Scene scene;
  env->describe_scene(scene);
  const render::View view = render::frame_scenes({&scene});
  render::SceneRasterizer rasterizer({width, height, supersample});
  render::Image image;
  int64_t pictures = 0;
  const auto start = bench::Clock::now();
  for (auto _ : state) {
    rasterizer.draw(scene, view, image);
    benchmark::DoNotOptimize(image.rgb.data());
    ++pictures;
  }
  const double picture_seconds = bench::seconds_since(start) / static_cast<double>(pictures);
  state.counters["pictures_per_s"] = 1.0 / picture_seconds;
  state.counters["steps_per_picture"] = picture_seconds / step_seconds;
}

BENCHMARK(BM_Picture)
    ->ArgNames({"width", "supersample"})
    ->Args({320, 1})
    ->Args({640, 1})
    ->Args({640, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace
}  // namespace tendril

BENCHMARK_MAIN();
