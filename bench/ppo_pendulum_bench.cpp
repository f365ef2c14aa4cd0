// PPO on Pendulum-v1 with Stable-Baselines3's default hyper-parameters (n_steps 2048, batch 64,
// 10 epochs, lr 3e-4, 64×64 tanh trunks for policy and value, clip 0.2, gradient norm 0.5):
// environment steps per second of the whole training loop (collection + updates), with 1 and
// 8 environments, and where the time goes. Also the bare cost of one minibatch step of the
// same network and loss in a tight loop (forward, PPO loss, backward, gradient-norm clip, Adam),
// the bound the update's per-minibatch cost approaches, computed as Ppo trains (nn::ActorCritic,
// ppo_loss, nn::Adam over the flat parameter vector).
//
//   build/bench/ppo_pendulum_bench [repeats]      (default 3; medians are reported)
//
// The baseline, measured in the same run: Stable-Baselines3 2.3.2's PPO with the same defaults
// on Gymnasium's Pendulum-v1, torch on one thread (sb3_baseline.hpp), 20,480 steps.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "sb3_baseline.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/adam.hpp"
#include "tendril/nn/gradient.hpp"
#include "tendril/nn/threads.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/ppo/ppo_loss.hpp"
#include "tendril/rl/rollout_minibatches.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

constexpr int64_t kStepsPerRun = 32768;  // 16 rollouts of 1 env, 2 rollouts of 8 envs
constexpr int64_t kBareMinibatches = 2000;

using bench::Clock;
using bench::median;
using bench::seconds_since;

struct LoopFigures {
  double wall_seconds = 0.0;
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0;
  double minibatches = 0.0;
  double steps_per_second() const { return static_cast<double>(kStepsPerRun) / wall_seconds; }
  double update_ms_per_minibatch() const { return 1e3 * update_seconds / minibatches; }
};

LoopFigures train_once(int n_envs) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  options.n_envs = n_envs;
  auto env = make_vec_env(options);
  Ppo ppo(*env, PpoConfig::sb3(), /*seed=*/0);
  LoopFigures figures;
  const auto start = Clock::now();
  ppo.learn(kStepsPerRun, [&](const Progress& progress) {
    figures.env_seconds += progress.env_seconds;
    figures.inference_seconds += progress.inference_seconds;
    figures.update_seconds += progress.update_seconds;
    for (const auto& [name, value] : progress.train) {
      if (name == "train/n_updates") figures.minibatches += value;
    }
    return true;
  });
  figures.wall_seconds = seconds_since(start);
  return figures;
}

// One minibatch of 64 rows through the SB3-default Pendulum actor-critic: PPO's loss (clip 0.2,
// value coefficient 0.5), its gradient, the gradient norm clipped to 0.5, an Adam step.
// Returns milliseconds per minibatch.
double bare_minibatch_ms() {
  nn::ActorCriticSpec spec;
  spec.observation_size = 3;
  spec.action_size = 1;
  const nn::ActorCritic network(spec);
  Eigen::VectorXf parameters(network.parameter_count());
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(network.parameter_count());
  Rng init_rng(0);
  network.initialize(parameters, init_rng);
  nn::Adam adam(network.parameter_count(), {.learning_rate = 3e-4, .epsilon = 1e-5});
  srand(0);
  const Eigen::MatrixXf observations = Eigen::MatrixXf::Random(3, 64);
  const Eigen::MatrixXf actions = Eigen::MatrixXf::Random(1, 64);
  const Eigen::RowVectorXf old_log_probs = Eigen::RowVectorXf::Random(64).array() - 1.0f;
  const Eigen::RowVectorXf old_values = Eigen::RowVectorXf::Random(64);
  const Eigen::RowVectorXf advantages = Eigen::RowVectorXf::Random(64);
  const Eigen::RowVectorXf returns = Eigen::RowVectorXf::Random(64);
  const RolloutMinibatch batch{observations, actions,    old_log_probs,
                               old_values,   advantages, returns};
  const PpoLossSettings settings{
      .clip_range = 0.2, .clip_range_vf = std::nullopt, .ent_coef = 0.0, .vf_coef = 0.5};
  nn::ActorCritic::Tape tape;
  PpoSampleGradients sample_gradients;
  const auto step = [&] {
    network.evaluate(parameters, batch.observations, batch.actions, tape);
    ppo_loss(batch, tape.log_prob, tape.entropy, tape.value, settings, sample_gradients);
    gradient.setZero();
    network.backward(parameters, tape, sample_gradients.log_prob, sample_gradients.entropy,
                     sample_gradients.value, gradient);
    nn::clip_grad_norm(gradient, 0.5);
    adam.step(parameters, gradient);
  };
  for (int i = 0; i < 100; ++i) step();
  const auto start = Clock::now();
  for (int64_t i = 0; i < kBareMinibatches; ++i) step();
  return 1e3 * seconds_since(start) / static_cast<double>(kBareMinibatches);
}

void print_loop(int n_envs, const std::vector<LoopFigures>& runs, std::optional<double> sb3) {
  std::vector<double> rates, env, inference, update, per_minibatch;
  for (const auto& run : runs) {
    rates.push_back(run.steps_per_second());
    env.push_back(run.env_seconds);
    inference.push_back(run.inference_seconds);
    update.push_back(run.update_seconds);
    per_minibatch.push_back(run.update_ms_per_minibatch());
  }
  const auto [slowest, fastest] = std::minmax_element(rates.begin(), rates.end());
  const std::string ratio = sb3 ? bench::ratio_text(median(rates) / *sb3) : "-";
  std::printf("| %d | %.0f | %.0f–%.0f | %s | %.2f | %.2f | %.2f | %.0f | %.3f |\n", n_envs,
              median(rates), *slowest, *fastest, ratio.c_str(), median(env), median(inference),
              median(update), runs.front().minibatches, median(per_minibatch));
}

int run(int repeats) {
  nn::configure_numerics(1);
  std::printf("PPO, Pendulum-v1, SB3 defaults, %lld env steps per run, median of %d runs\n\n",
              static_cast<long long>(kStepsPerRun), repeats);
  const std::optional<double> sb3 = bench::sb3_pendulum_steps_per_second("ppo", 20480);
  if (sb3) {
    std::printf("Stable-Baselines3 2.3.2, same settings, this run: %.0f steps/s\n\n", *sb3);
  } else {
    std::printf("Stable-Baselines3 baseline unavailable (../shared/vendor or anchors missing)\n\n");
  }
  std::printf(
      "| envs | steps/s | range | vs SB3 | env s | inference s | update s | minibatches "
      "| update ms/minibatch |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (int n_envs : {1, 8}) {
    std::vector<LoopFigures> runs;
    for (int r = 0; r < repeats; ++r) runs.push_back(train_once(n_envs));
    print_loop(n_envs, runs, sb3);
  }
  std::printf("\nBare minibatch step (64 rows: evaluate, PPO loss, gradient, clip, Adam):\n");
  std::vector<double> bare;
  for (int r = 0; r < repeats; ++r) bare.push_back(bare_minibatch_ms());
  const auto [lowest, highest] = std::minmax_element(bare.begin(), bare.end());
  std::printf("  %.3f ms (range %.3f–%.3f)\n", median(bare), *lowest, *highest);
  return 0;
}

}  // namespace
}  // namespace tendril::rl

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  return tendril::rl::run(repeats);
}
