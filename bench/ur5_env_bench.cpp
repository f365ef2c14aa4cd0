// Environment steps per second of UR5/Reach-v0 on one core, against the MuJoCo physics it runs
// on, measured in the same run.
//
//   build/bench/ur5_env_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// BM_Ur5Reach: the registered environment (time limit included) under uniformly random actions,
// resetting when an episode ends — random joint motions hit the box or the table within a few
// hundred steps, so resets (placing the arm, drawing a target) are part of the cost.
// BM_Ur5ReachHolding: the same environment under zero actions, no resets: the cost of a step.
// BM_MujocoSteps: the baseline, ten plain mj_step calls of the same compiled model (one
// environment step's physics without the servo's bias compensation, observation or reward).
// `overhead_vs_mujoco` = environment time per step / mj_step time per step (1 = no overhead).
// Times are the thread's CPU time (one core, whatever else the machine runs).
//
// The seed (UR5 in MuJoCo through Python, Gymnasium and CleanRL on an Intel Core Ultra 7 155H)
// reports whole-training speeds only: PPO ≈ 1,300 steps/s with 8 envs (its 1M steps in 30 min
// are 556 steps/s) and SAC 35–270 steps/s; `docs/results/ur5.md` sets tendril's training speeds
// beside them.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <ctime>

#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/physics/rigid/ur5_arm.hpp"

namespace tendril {
namespace {

constexpr int kFrameSkip = 10;  // UR5/Reach-v0's physics steps per action

// CPU seconds of this thread: on a shared machine the time the work itself took.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Mean seconds of one environment step's physics alone, measured now (the baseline).
double mujoco_seconds_per_env_step() {
  physics::Ur5Arm arm;
  arm.place((physics::Ur5Arm::Joints() << 2.69, -1.80, 2.76, -2.53, -1.571, 0.0).finished());
  physics::MujocoSim sim = arm.sim();
  constexpr int kSteps = 2000;
  const double start = thread_seconds();
  for (int i = 0; i < kSteps * kFrameSkip; ++i) mj_step(sim.model(), sim.data());
  return (thread_seconds() - start) / kSteps;
}

void run_env(benchmark::State& state, bool random_actions) {
  const double baseline = mujoco_seconds_per_env_step();
  const std::unique_ptr<Env> env = envs::make("UR5/Reach-v0");
  Rng rng(7);
  env->reset(0);
  int64_t steps = 0, episodes = 0;
  const Action still = Action::Zero(6);
  const double start = thread_seconds();
  for (auto _ : state) {
    const Action action = random_actions ? env->action_space().sample(rng) : still;
    const Step step = env->step(action);
    benchmark::DoNotOptimize(step.observation.data());
    if (step.terminated || step.truncated) {
      env->reset();
      ++episodes;
    }
    ++steps;
  }
  const double seconds = thread_seconds() - start;
  state.counters["env_steps_per_s"] = static_cast<double>(steps) / seconds;
  state.counters["overhead_vs_mujoco"] = (seconds / static_cast<double>(steps)) / baseline;
  state.counters["episodes"] = static_cast<double>(episodes);
}

void BM_Ur5Reach(benchmark::State& state) { run_env(state, true); }
void BM_Ur5ReachHolding(benchmark::State& state) { run_env(state, false); }

void BM_MujocoSteps(benchmark::State& state) {
  physics::Ur5Arm arm;
  arm.place((physics::Ur5Arm::Joints() << 2.69, -1.80, 2.76, -2.53, -1.571, 0.0).finished());
  physics::MujocoSim sim = arm.sim();
  int64_t steps = 0;
  const double start = thread_seconds();
  for (auto _ : state) {
    for (int i = 0; i < kFrameSkip; ++i) mj_step(sim.model(), sim.data());
    ++steps;
  }
  state.counters["env_steps_per_s"] = static_cast<double>(steps) / (thread_seconds() - start);
}

BENCHMARK(BM_Ur5Reach)->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK(BM_Ur5ReachHolding)->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK(BM_MujocoSteps)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

}  // namespace
}  // namespace tendril

BENCHMARK_MAIN();
