// Environment steps per second of the pneumatic arm's reaching task (seed 002 §IV-A) inside a
// learned model, PneumaticArm/LearnedReach-v0, against the same task on the twin,
// PneumaticArm/Reach-v0, measured in the same run with the same random deltas (resets included:
// the twin settles 2 s at each, the model starts at rest). Also the torch-free stand-in model
// (LinearArmModel), which shows the task's own cost. One LibTorch thread, as the trainer uses.
//
//   build/bench/pneumatic_learned_bench <model file or fit run> <data set for the rest> [repeats]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/torch_threads.hpp"
#include "tendril/envs/registry.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using namespace tendril;

double steps_per_second(const std::string& id, const Config& params, int repeats) {
  std::vector<double> rates;
  for (int r = 0; r < repeats; ++r) {
    const auto env = envs::make(id, params);
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
  std::sort(rates.begin(), rates.end());
  return rates[rates.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <model file or fit run> <data set for the rest> [repeats]\n",
                 argv[0]);
    return 2;
  }
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
  dynamics::use_one_torch_thread();
  dynamics::install_model_loader();
  const Config learned =
      Config::parse(std::string("model: ") + argv[1] + "\nrest_from: " + argv[2]);
  const double twin = steps_per_second("PneumaticArm/Reach-v0", Config(), repeats);
  const double model = steps_per_second("PneumaticArm/LearnedReach-v0", learned, repeats);
  const double stand_in = steps_per_second("PneumaticArm/LearnedReach-v0", Config(), repeats);
  std::printf("pneumatic arm reaching task, random deltas, resets included, median of %d\n",
              repeats);
  std::printf("  %-46s %9.0f env steps/s  (1.00)\n", "PneumaticArm/Reach-v0 (twin, default)", twin);
  std::printf("  %-46s %9.0f env steps/s  (%.1f x the twin)\n",
              "PneumaticArm/LearnedReach-v0 (the fitted model)", model, model / twin);
  std::printf("  %-46s %9.0f env steps/s  (%.1f x the twin)\n",
              "PneumaticArm/LearnedReach-v0 (linear stand-in)", stand_in, stand_in / twin);
  return 0;
}
