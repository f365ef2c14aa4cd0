// SAC and TD3 on Pendulum-v1, one env, one gradient step per env step: environment steps per
// second of the whole training loop (collection, replay sampling, updates), next to the bound
// set by the network passes alone — every forward and backward pass of one gradient step, in a
// tight loop on a fixed batch, with nothing else (no env, sampling, optimizer or target update).
// The loop's rate divided by the bound's is the fraction of the compute bound reached. Also the
// same passes through LibTorch autograd (one thread), as a reference for the kernels.
//
// Two sizes: SB3's SAC defaults (256×256 networks, batch 256) and small networks (64×64,
// batch 100), each with the networks' products on one and on two threads (`learner_threads`;
// the environment runs in the calling thread, so the second core is free). The LibTorch
// reference always runs on one thread, as SB3 runs best. Stable-Baselines3 2.3.2's own SAC with
// its defaults (256×256, batch 256) is measured in the same run (sb3_baseline.hpp).
//
//   build/bench/off_policy_bench [repeats]      (default 3; medians are reported)
#include <torch/torch.h>

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
#include "tendril/nn/blas.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/threads.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/td3/td3.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

using bench::Clock;
using bench::median;
using bench::seconds_since;

struct Case {
  std::string algorithm;  // sac | td3
  int64_t hidden;
  int64_t batch;
  int64_t measured_steps;
  int threads;  // learner_threads
};

constexpr int64_t kObservations = 3, kActions = 1;  // Pendulum-v1
constexpr int64_t kWarmup = 1000;                   // steps before the measurement

std::string algo_yaml(const Case& c) {
  return "learning_starts: 100\nbatch_size: " + std::to_string(c.batch) + "\nnet_arch: [" +
         std::to_string(c.hidden) + ", " + std::to_string(c.hidden) +
         "]\nlog_interval: 100\nlearner_threads: " + std::to_string(c.threads) + "\n";
}

struct LoopFigures {
  double steps_per_second = 0.0;
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0, wall_seconds = 0.0;
};

LoopFigures train_loop(const Case& c) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  auto env = make_vec_env(options);
  const Config algo = Config::parse(algo_yaml(c));
  std::unique_ptr<OffPolicyAlgorithm> agent;
  if (c.algorithm == "sac") {
    agent = std::make_unique<Sac>(*env, SacConfig::from_config(algo), 0);
  } else {
    agent = std::make_unique<Td3>(*env, Td3Config::from_config(algo, rl::Td3Variant::kTd3), 0);
  }
  agent->learn(kWarmup);
  LoopFigures figures;
  const auto start = Clock::now();
  agent->learn(kWarmup + c.measured_steps, [&](const Progress& p) {
    figures.env_seconds += p.env_seconds;
    figures.inference_seconds += p.inference_seconds;
    figures.update_seconds += p.update_seconds;
    return true;
  });
  figures.wall_seconds = seconds_since(start);
  figures.steps_per_second = static_cast<double>(c.measured_steps) / figures.wall_seconds;
  return figures;
}

// Every network pass of one SAC or TD3 gradient step with nn::DenseMlp, as the algorithms run
// them. Returns seconds per gradient step.
double bare_passes(const Case& c, int64_t steps) {
  using nn::DenseMlp;
  nn::set_blas_threads(c.threads);
  const bool sac = c.algorithm == "sac";
  const DenseMlp actor({kObservations, c.hidden, c.hidden, sac ? 2 * kActions : kActions},
                       nn::Activation::kRelu, /*tanh_output=*/!sac);
  const DenseMlp critic({kObservations + kActions, c.hidden, c.hidden, 1}, nn::Activation::kRelu);
  Rng rng(0);
  Eigen::VectorXf actor_parameters(actor.parameter_count()), actor_gradient;
  std::vector<Eigen::VectorXf> critic_parameters(2, Eigen::VectorXf(critic.parameter_count()));
  std::vector<Eigen::VectorXf> critic_gradients(2);
  actor.initialize(actor_parameters, rng);
  for (auto& parameters : critic_parameters) critic.initialize(parameters, rng);
  actor_gradient = Eigen::VectorXf::Zero(actor.parameter_count());
  for (auto& gradient : critic_gradients)
    gradient = Eigen::VectorXf::Zero(critic.parameter_count());
  const Eigen::MatrixXf observations = Eigen::MatrixXf::Random(kObservations, c.batch);
  const Eigen::MatrixXf critic_inputs = Eigen::MatrixXf::Random(kObservations + kActions, c.batch);
  const Eigen::MatrixXf value_gradient = Eigen::MatrixXf::Constant(1, c.batch, 1.0f / c.batch);
  DenseMlp::Tape actor_tape, next_tape, critic_tape;
  std::vector<Eigen::MatrixXf> scratch;
  Eigen::MatrixXf input_gradient;
  Eigen::VectorXf no_gradient;
  const auto step = [&](int64_t index) {
    actor.forward(actor_parameters, observations, next_tape);  // a' (SAC: π; TD3: target π)
    for (int i = 0; i < 2; ++i) critic.forward(critic_parameters[i], critic_inputs, critic_tape);
    for (int i = 0; i < 2; ++i) {  // critic regression
      critic.forward(critic_parameters[i], critic_inputs, critic_tape);
      critic.backward(critic_parameters[i], critic_tape, value_gradient, critic_gradients[i],
                      nullptr, scratch);
    }
    if (!sac && index % 2 == 1) return;  // TD3's delayed actor step
    actor.forward(actor_parameters, observations, actor_tape);
    for (int i = 0; i < (sac ? 2 : 1); ++i) {  // ∂Q/∂a for the actor
      critic.forward(critic_parameters[i], critic_inputs, critic_tape);
      critic.backward(critic_parameters[i], critic_tape, value_gradient, no_gradient,
                      &input_gradient, scratch);
    }
    const Eigen::MatrixXf head_gradient =
        Eigen::MatrixXf::Constant(actor.output_size(), c.batch, 1.0f / static_cast<float>(c.batch));
    actor.backward(actor_parameters, actor_tape, head_gradient, actor_gradient, nullptr, scratch);
  };
  for (int64_t i = 0; i < 20; ++i) step(i);
  const auto start = Clock::now();
  for (int64_t i = 0; i < steps; ++i) step(i);
  return seconds_since(start) / static_cast<double>(steps);
}

// The same passes through LibTorch modules and autograd (SB3's computation without Python).
double libtorch_passes(const Case& c, int64_t steps) {
  torch::set_num_threads(1);
  const bool sac = c.algorithm == "sac";
  const auto mlp = [&](int64_t in, int64_t out) {
    return torch::nn::Sequential(torch::nn::Linear(in, c.hidden), torch::nn::ReLU(),
                                 torch::nn::Linear(c.hidden, c.hidden), torch::nn::ReLU(),
                                 torch::nn::Linear(c.hidden, out));
  };
  torch::nn::Sequential actor = mlp(kObservations, sac ? 2 * kActions : kActions);
  std::vector<torch::nn::Sequential> critics{mlp(kObservations + kActions, 1),
                                             mlp(kObservations + kActions, 1)};
  const torch::Tensor observations = torch::randn({c.batch, kObservations});
  const torch::Tensor actions = torch::randn({c.batch, kActions});
  const torch::Tensor targets = torch::randn({c.batch, 1});
  const auto step = [&](int64_t index) {
    {
      torch::NoGradGuard no_grad;
      const torch::Tensor next = torch::tanh(actor->forward(observations).narrow(1, 0, kActions));
      for (auto& critic : critics) critic->forward(torch::cat({observations, next}, 1));
    }
    torch::Tensor critic_loss = torch::zeros({});
    for (auto& critic : critics) {
      critic_loss =
          critic_loss +
          torch::mse_loss(critic->forward(torch::cat({observations, actions}, 1)), targets);
    }
    critic_loss.backward();
    if (!sac && index % 2 == 1) return;
    const torch::Tensor pi = torch::tanh(actor->forward(observations).narrow(1, 0, kActions));
    torch::Tensor q = critics[0]->forward(torch::cat({observations, pi}, 1));
    if (sac) q = torch::min(q, critics[1]->forward(torch::cat({observations, pi}, 1)));
    (-q.mean()).backward();
  };
  for (int64_t i = 0; i < 10; ++i) step(i);
  const auto start = Clock::now();
  for (int64_t i = 0; i < steps; ++i) step(i);
  return seconds_since(start) / static_cast<double>(steps);
}

int run(int repeats) {
  torch::set_num_threads(1);
  const std::vector<Case> cases{{"sac", 256, 256, 400, 1}, {"sac", 256, 256, 600, 2},
                                {"td3", 256, 256, 600, 1}, {"td3", 256, 256, 900, 2},
                                {"sac", 64, 100, 6000, 1}, {"sac", 64, 100, 6000, 2},
                                {"td3", 64, 100, 8000, 1}, {"td3", 64, 100, 8000, 2}};
  std::printf(
      "Off-policy training on Pendulum-v1, 1 env, 1 gradient step per env step; medians of %d "
      "runs\n\n",
      repeats);
  const std::optional<double> sb3 = bench::sb3_pendulum_steps_per_second("sac", 1500);
  if (sb3) {
    std::printf("Stable-Baselines3 2.3.2 SAC (256x256, batch 256), this run: %.0f steps/s\n\n",
                *sb3);
  } else {
    std::printf("Stable-Baselines3 baseline unavailable (../shared/vendor or anchors missing)\n\n");
  }
  std::printf(
      "| algorithm | networks, batch | learner threads | loop steps/s | bound steps/s (bare "
      "passes) | loop / bound | "
      "LibTorch passes steps/s | loop: env s | inference s | update s | SAC 256 loop vs SB3 |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const Case& c : cases) {
    std::vector<double> loop_rates, bound_rates, torch_rates, env, inference, update;
    for (int r = 0; r < repeats; ++r) {
      const LoopFigures loop = train_loop(c);
      loop_rates.push_back(loop.steps_per_second);
      env.push_back(loop.env_seconds);
      inference.push_back(loop.inference_seconds);
      update.push_back(loop.update_seconds);
      const int64_t bare_steps = c.measured_steps / 2;
      bound_rates.push_back(1.0 / bare_passes(c, bare_steps));
      torch_rates.push_back(1.0 / libtorch_passes(c, bare_steps));
    }
    const bool sb3_sized = c.algorithm == "sac" && c.hidden == 256 && c.batch == 256;
    const std::string ratio = sb3 && sb3_sized ? bench::ratio_text(median(loop_rates) / *sb3) : "-";
    std::printf(
        "| %s | %lldx%lld, %lld | %d | %.0f | %.0f | %.2f | %.0f | %.2f | %.2f | %.2f | %s |\n",
        c.algorithm == "sac" ? "SAC" : "TD3", static_cast<long long>(c.hidden),
        static_cast<long long>(c.hidden), static_cast<long long>(c.batch), c.threads,
        median(loop_rates), median(bound_rates), median(loop_rates) / median(bound_rates),
        median(torch_rates), median(env), median(inference), median(update), ratio.c_str());
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace tendril::rl

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  return tendril::rl::run(repeats);
}
