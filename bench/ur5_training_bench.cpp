// Training speed on UR5/Reach-v0 (seed 004 reports ≈ 556–1,300 environment steps per second for
// PPO with 8 envs and 35–270 for SAC, Sec. 3.2 and Table 1): environment steps per second of the
// whole training loop (collection + updates) of the experiment files in configs/ur5/, and where
// the time goes.
//
//   build/bench/ur5_training_bench [repeats]      (default 1; medians are reported)
//
// Runs: ppo_tuned.yaml (8 envs × 2048 steps, 10 epochs of 32 minibatches: two rollouts),
// sac_model_a.yaml (4 envs, 16 gradient steps every 256 vector steps), sac_model_b.yaml (2 envs,
// 2 every 2) and sac_cleanrl.yaml (1 env, 1 every step); SAC's random warm-up is shortened to
// learning_starts = 1024 so that most measured steps train.
// The baseline, measured in the same run: the same vector env (the same copies, time limit,
// statistics and normalisation) stepped under uniformly random actions for as many steps with no
// learner; "× env" is the training loop's time over that bare stepping time.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/threads.hpp"
#include "tendril/rl/experiment.hpp"

namespace tendril::rl {
namespace {

using bench::Clock;
using bench::median;
using bench::seconds_since;

struct Case {
  const char* file;    // under configs/ur5/
  int64_t steps;       // environment steps, over all envs
  bool short_warm_up;  // learning_starts = 1024
};

struct Figures {
  double training_seconds = 0.0, bare_seconds = 0.0;
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0;
};

Experiment load(const Case& c) {
  Config config = Config::load_file(std::string(TENDRIL_CONFIG_DIR) + "/ur5/" + c.file);
  config.set("eval.freq", "0");
  config.set("checkpoint_freq", "0");
  config.set("n_timesteps", std::to_string(c.steps));
  if (c.short_warm_up) config.set("algo.learning_starts", "1024");
  return Experiment::from_config(config);
}

// The same vector env under uniformly random actions in [−1, 1] (the env's action units).
double bare_stepping_seconds(const Experiment& experiment, int64_t steps) {
  auto env = make_vec_env(experiment.env);
  env->reset(experiment.seed);
  const int n = env->num_envs();
  envs::BatchMatrix actions(n, env->action_space().size());
  Rng rng(experiment.seed, /*stream=*/7);
  const auto start = Clock::now();
  for (int64_t done = 0; done < steps; done += n) {
    for (Eigen::Index i = 0; i < actions.size(); ++i) {
      actions.data()[i] = static_cast<float>(rng.uniform(-1.0, 1.0));
    }
    env->step(actions);
  }
  return seconds_since(start);
}

Figures measure(const Case& c) {
  const Experiment experiment = load(c);
  Figures figures;
  auto env = make_vec_env(experiment.env);
  auto algorithm = make_algorithm(experiment, *env);
  const auto start = Clock::now();
  algorithm->learn(experiment.n_timesteps, [&](const Progress& progress) {
    figures.env_seconds += progress.env_seconds;
    figures.inference_seconds += progress.inference_seconds;
    figures.update_seconds += progress.update_seconds;
    return true;
  });
  figures.training_seconds = seconds_since(start);
  figures.bare_seconds = bare_stepping_seconds(experiment, experiment.n_timesteps);
  return figures;
}

int run(int repeats) {
  nn::configure_numerics(1);
  std::printf("UR5/Reach-v0 training loops, one thread, median of %d run(s)\n\n", repeats);
  std::printf(
      "| experiment | env steps | training steps/s | bare env steps/s | × env | env s | "
      "inference s | update s |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  const Case cases[] = {{"ppo_tuned.yaml", 32768, false},
                        {"sac_model_a.yaml", 8192, true},
                        {"sac_model_b.yaml", 2048, true},
                        {"sac_cleanrl.yaml", 2048, true}};
  for (const Case& c : cases) {
    std::vector<double> rates, bare_rates, ratios, env, inference, update;
    for (int r = 0; r < repeats; ++r) {
      const Figures f = measure(c);
      rates.push_back(static_cast<double>(c.steps) / f.training_seconds);
      bare_rates.push_back(static_cast<double>(c.steps) / f.bare_seconds);
      ratios.push_back(f.training_seconds / f.bare_seconds);
      env.push_back(f.env_seconds);
      inference.push_back(f.inference_seconds);
      update.push_back(f.update_seconds);
    }
    std::printf("| %s | %lld | %.0f | %.0f | %.1fx | %.2f | %.2f | %.2f |\n", c.file,
                static_cast<long long>(c.steps), median(rates), median(bare_rates), median(ratios),
                median(env), median(inference), median(update));
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace tendril::rl

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1;
  return tendril::rl::run(repeats);
}
