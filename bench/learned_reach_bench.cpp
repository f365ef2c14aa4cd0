// Seed 001 ch. 5's training loop on the learned model of the SMA limb, timed:
//  1. environment steps per second of SmaLimb/LearnedReach-v0 for 10 envs — one batched model
//     call per step (the registry's LearnedReachVecEnv, what training uses) against 10 single
//     envs in a ThreadedVecEnv on one thread (one model call each);
//  2. SAC gradient steps per second (batch 256, actor and critics 256 wide, window 100) with no
//     head, a frozen LK Encoder head (its features kept in the replay buffer) and a trainable one,
//     against the same update in PyTorch (bench/sac_lk_head_pytorch.py, Debian's python3-torch,
//     one thread) in this run, whose frozen head runs on every batch as in the author's code;
//  3. SAC training steps per second (environment steps of the whole loop: collection, batched
//     model, head, one gradient step per vector step) for the three.
// Times are this thread's processor time (CLOCK_THREAD_CPUTIME_ID; Python's time.thread_time),
// medians of repetitions: on a shared machine other programs inflate wall time, not this.
//
//   learned_reach_bench <model file or fit run> [--python /usr/bin/python3] [--repeats 3]
#include <time.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/policy_heads.hpp"
#include "tendril/dynamics/torch_threads.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"
#include "tendril/rl/sac/sac.hpp"

namespace {

using namespace tendril;

double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

constexpr const char* kId = "SmaLimb/LearnedReach-v0";
constexpr int kEnvs = 10;

Config env_params(const std::string& model) {
  return Config::parse("model: " + model + "\nhistory: 100\n");
}

double vector_steps_per_second(envs::VecEnv& env, int steps) {
  env.reset(0);
  Rng rng(1);
  envs::BatchMatrix actions(env.num_envs(), 2);
  const double start = thread_seconds();
  for (int t = 0; t < steps; ++t) {
    for (Eigen::Index i = 0; i < actions.size(); ++i) {
      actions.data()[i] = static_cast<float>(rng.uniform(-10.0, 10.0));
    }
    env.step(actions);
  }
  return steps * env.num_envs() / (thread_seconds() - start);
}

class TimedSac : public rl::Sac {
 public:
  using Sac::Sac;
  void gradient_steps(int64_t steps) { train(steps, 1.0); }
};

rl::SacConfig sac_config(const std::string& head, const std::string& model, int64_t starts) {
  std::string text =
      "buffer_size: 100000\nlearning_starts: " + std::to_string(starts) +
      "\nbatch_size: 256\nlearning_rate: 5.0e-4\ntarget_update_interval: 2\npolicy_delay: 2\n"
      "compensate_policy_delay: true\nmax_grad_norm: 1.0\nent_coef: auto_0.2\nnet_arch: [256]\n";
  if (head != "none") {
    text += "head: {kind: lk_encoder, model: " + model +
            ", trainable: " + (head == "trainable" ? "true" : "false") + "}\n";
  }
  return rl::SacConfig::from_config(Config::parse(text));
}

struct SacRates {
  double gradient_steps = 0.0, training_steps = 0.0;
};

SacRates sac_rates(const std::string& head, const std::string& model, int repeats) {
  auto env = envs::make_vector(kId, env_params(model), kEnvs);
  TimedSac sac(*env, sac_config(head, model, 2000), 0);
  sac.learn(2000);  // random warm-up fills the buffer
  std::vector<double> gradient, training;
  const int steps = head == "trainable" ? 4 : 20;
  for (int r = 0; r < repeats; ++r) {
    double start = thread_seconds();
    sac.gradient_steps(steps);
    gradient.push_back(steps / (thread_seconds() - start));
    const int64_t before = sac.num_timesteps();
    start = thread_seconds();
    sac.learn(before + 10 * steps);
    training.push_back(static_cast<double>(sac.num_timesteps() - before) /
                       (thread_seconds() - start));
  }
  return {bench::median(gradient), bench::median(training)};
}

double pytorch_gradient_steps(const std::string& python, bool frozen) {
  const std::string command = "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 " + python + " " +
                              TENDRIL_BENCH_DIR + "/sac_lk_head_pytorch.py --steps 10" +
                              (frozen ? " --frozen" : "");
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return 0.0;
  double value = 0.0;
  char line[256];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    std::sscanf(line, "gradient_steps_per_second %lf", &value);
  }
  if (pclose(pipe) != 0) {
    std::fprintf(stderr, "PyTorch baseline failed: %s\n", command.c_str());
    return 0.0;
  }
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <model file or fit run> [--python P] [--repeats R]\n", argv[0]);
    return 2;
  }
  const std::string model = argv[1];
  std::string python = "/usr/bin/python3";
  int repeats = 3;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--python") {
      python = argv[i + 1];
    } else if (flag == "--repeats") {
      repeats = std::max(1, std::stoi(argv[i + 1]));
    } else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  dynamics::use_one_torch_thread();
  dynamics::install_model_loader();
  dynamics::install_policy_heads();

  std::printf("SmaLimb/LearnedReach-v0, %d envs, history 100, random throttles, median of %d\n",
              kEnvs, repeats);
  std::vector<double> batched, threaded;
  for (int r = 0; r < repeats; ++r) {
    auto vector = envs::make_vector(kId, env_params(model), kEnvs);
    batched.push_back(vector_steps_per_second(*vector, 100));
    envs::ThreadedVecEnv singles(kEnvs, [&](int) -> std::unique_ptr<Env> {
      return std::make_unique<envs::EpisodeStatistics>(envs::make(kId, env_params(model)));
    });
    threaded.push_back(vector_steps_per_second(singles, 100));
  }
  const double one_call = bench::median(batched), separate = bench::median(threaded);
  std::printf("  %-52s %9.0f env steps/s  (%.2f x)\n",
              "one batched model call (LearnedReachVecEnv)", one_call, one_call / separate);
  std::printf("  %-52s %9.0f env steps/s  (1.00)\n", "10 single envs, ThreadedVecEnv, 1 thread",
              separate);
  std::fflush(stdout);

  std::printf("\nSAC, batch 256, actor/critics [256], LK Encoder head = the model's encoder\n");
  std::printf("  %-22s %16s %16s %8s %18s\n", "head", "tendril grad/s", "PyTorch grad/s", "ratio",
              "tendril env steps/s");
  for (const std::string head : {"none", "frozen", "trainable"}) {
    const SacRates ours = sac_rates(head, model, repeats);
    double theirs = 0.0;
    if (head != "none") {
      std::vector<double> runs;
      for (int r = 0; r < repeats; ++r)
        runs.push_back(pytorch_gradient_steps(python, head == "frozen"));
      theirs = bench::median(runs);
    }
    std::printf("  %-22s %16.1f %16.1f %8.2f %18.0f\n", head.c_str(), ours.gradient_steps, theirs,
                theirs > 0 ? ours.gradient_steps / theirs : 0.0, ours.training_steps);
    std::fflush(stdout);
  }
  return 0;
}
