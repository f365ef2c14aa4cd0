// The pneumatic arm's twin (seed 002): control steps (0.1 s of arm time) per second at several
// rod resolutions and time steps, each against the finest one measured in the same run — its
// speed ratio and how far module 3's tip strays from it (mm) under the same 60 s of the data
// protocol's saturating pressure signal, stochastic effects off. Then the default twin with
// every stochastic effect on, and PneumaticArm/Reach-v0 steps per second with random deltas.
// "× real time" divides by the real arm's 10 control steps per second.
//
//   build-lite/bench/pneumatic_twin_bench [repeats]      (default 3; medians are reported)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench_timing.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"
#include "tendril/envs/pneumatic/saturating_signal.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {
namespace {

using bench::Clock;
using bench::median;

constexpr int kControlSteps = 600;  // 60 s of arm time
constexpr double kRealArmStepsPerSecond = 10.0;

struct Resolution {
  int elements_per_module;
  double time_step;
};

struct Run {
  double steps_per_second = 0.0;
  std::vector<Eigen::Vector3d> tips;  // module 3, mm, after each step
};

Run run(const Resolution& resolution, bool stochastic, int repeats) {
  physics::pneumatic::PneumaticArmSpec spec;
  spec.elements_per_module = resolution.elements_per_module;
  spec.time_step = resolution.time_step;
  if (stochastic) {
    spec.effects.drift = spec.effects.hysteresis = true;
    spec.effects.imbalance = spec.effects.sensor_noise = true;
  }
  std::vector<Action> commands;
  SaturatingSignal signal(SaturatingSignalSpec{}, Rng(0));
  for (int k = 0; k < kControlSteps; ++k) commands.push_back(signal.next(0.1).cast<float>());

  Run result;
  std::vector<double> rates;
  for (int r = 0; r < repeats; ++r) {
    RobotEnv env(spec, 0.1, false);
    env.reset(0);
    result.tips.clear();
    const auto start = Clock::now();
    for (const Action& action : commands) {
      const Step step = env.step(action);
      result.tips.emplace_back(step.observation.tail<3>().cast<double>());
    }
    rates.push_back(kControlSteps / std::chrono::duration<double>(Clock::now() - start).count());
  }
  result.steps_per_second = median(rates);
  return result;
}

double reach_steps_per_second(int repeats) {
  std::vector<double> rates;
  for (int r = 0; r < repeats; ++r) {
    const auto env = make("PneumaticArm/Reach-v0");
    Rng rng(1);
    env->reset(0);
    const int steps = 1500;
    const auto start = Clock::now();
    for (int k = 0; k < steps; ++k) {
      const Step step = env->step(env->action_space().sample(rng));
      if (step.terminated || step.truncated) env->reset();
    }
    rates.push_back(steps / std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(rates);
}

}  // namespace
}  // namespace tendril::envs::pneumatic

int main(int argc, char** argv) {
  using namespace tendril::envs::pneumatic;
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const Resolution reference{20, 1.0e-4};
  const std::vector<Resolution> resolutions = {
      {10, 2.0e-4}, {6, 4.0e-4}, {6, 5.0e-4}, {4, 5.0e-4}, {3, 6.25e-4}};

  std::printf(
      "pneumatic arm twin, %d control steps of 0.1 s under the saturating signal, "
      "median of %d\n\n",
      kControlSteps, repeats);
  std::printf("%9s %9s %14s %13s %14s %21s\n", "elements", "dt [ms]", "control st/s", "x real time",
              "x reference", "tip-3 dev. mean/max");
  const Run base = run(reference, false, 1);
  std::printf("%9d %9.3f %14.0f %13.0f %14.2f %21s\n", 3 * reference.elements_per_module,
              1e3 * reference.time_step, base.steps_per_second,
              base.steps_per_second / kRealArmStepsPerSecond, 1.0, "(reference)");
  for (const Resolution& resolution : resolutions) {
    const Run result = run(resolution, false, repeats);
    double mean = 0.0, largest = 0.0;
    for (int k = 0; k < kControlSteps; ++k) {
      const double deviation = (result.tips[k] - base.tips[k]).norm();
      mean += deviation / kControlSteps;
      largest = std::max(largest, deviation);
    }
    std::printf("%9d %9.3f %14.0f %13.0f %14.2f %12.2f / %5.2f mm\n",
                3 * resolution.elements_per_module, 1e3 * resolution.time_step,
                result.steps_per_second, result.steps_per_second / kRealArmStepsPerSecond,
                result.steps_per_second / base.steps_per_second, mean, largest);
  }
  const Run stochastic = run({6, 5.0e-4}, true, repeats);
  std::printf(
      "\ndefault twin (18 elements, 0.5 ms) with every stochastic effect on: %.0f control "
      "steps/s (%.0f x real time)\n",
      stochastic.steps_per_second, stochastic.steps_per_second / kRealArmStepsPerSecond);
  std::printf("PneumaticArm/Reach-v0, random deltas, resets included: %.0f env steps/s\n",
              reach_steps_per_second(repeats));
  return 0;
}
