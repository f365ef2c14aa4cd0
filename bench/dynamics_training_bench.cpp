// Training throughput of seed 001's LSTM and Seq2Seq-with-attention dynamics models (windows per
// second of Adam steps: forward, MSE, backward, gradient-value clipping, update), tendril
// against PyTorch (Debian's python3-torch, bench/dynamics_training_pytorch.py) with the same
// architecture, batch, window and one thread, measured in this run; then the cost of one batched
// prediction step (envs::DynamicsModel::predict) for N = 1 and N = 16 environments. Times are
// the calling thread's processor time (CLOCK_THREAD_CPUTIME_ID; Python's time.thread_time), medians
// over batches or repetitions: on a shared machine other programs inflate wall time, not this.
//
//   dynamics_training_bench [--hidden 64] [--layers 2] [--window 100] [--batch 256]
//                           [--batches 10] [--repeats 3] [--python /usr/bin/python3]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/torch_threads.hpp"

namespace {

using namespace tendril;
using namespace tendril::dynamics;

// Seconds of processor time used by the calling thread.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct Settings {
  int hidden = 64, layers = 2, heads = 4, window = 100, batch = 256, batches = 10, repeats = 3;
  std::string python = "/usr/bin/python3";
};

ModelDescription description(Architecture kind, const Settings& s) {
  ModelDescription d;
  d.architecture.kind = kind;
  d.architecture.hidden_size = s.hidden;
  d.architecture.layers = s.layers;
  d.architecture.heads = s.heads;
  d.architecture.window = s.window;
  d.normalizer = Normalizer::identity(6);
  d.state_names = {"theta_x", "theta_y", "omega_x", "omega_y"};
  d.input_names = {"u_x", "u_y"};
  d.sample_period = 0.07;
  return d;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The batch size over the median time of one Adam step.
double tendril_windows_per_second(Architecture kind, const Settings& s) {
  Model model(description(kind, s), 0);
  SequenceNetwork& network = model.network();
  network.train();
  torch::optim::Adam adam(network.parameters(), torch::optim::AdamOptions(1e-3));
  const torch::Tensor windows = torch::randn({s.batch, s.window, 6});
  const torch::Tensor targets = torch::randn({s.batch, 4});
  auto step = [&] {
    adam.zero_grad();
    const torch::Tensor loss =
        torch::mse_loss(network.forward(model.network_input(windows)), targets);
    loss.backward();
    torch::nn::utils::clip_grad_value_(network.parameters(), 1.0);
    adam.step();
    return loss.item<double>();
  };
  step();  // warm-up
  std::vector<double> times;
  for (int b = 0; b < s.batches; ++b) {
    const double start = thread_seconds();
    step();
    times.push_back(thread_seconds() - start);
  }
  return s.batch / median(times);
}

double pytorch_windows_per_second(Architecture kind, const Settings& s) {
  // One OpenBLAS thread too, as tendril's dynamics::use_one_torch_thread sets.
  const std::string command =
      "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 " + s.python + " " + TENDRIL_BENCH_DIR +
      "/dynamics_training_pytorch.py --architecture " + architecture_name(kind) + " --hidden " +
      std::to_string(s.hidden) + " --layers " + std::to_string(s.layers) + " --heads " +
      std::to_string(s.heads) + " --window " + std::to_string(s.window) + " --batch " +
      std::to_string(s.batch) + " --batches " + std::to_string(s.batches) + " --threads 1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return 0.0;
  double value = 0.0;
  char line[256];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    std::sscanf(line, "windows_per_second %lf", &value);
  }
  if (pclose(pipe) != 0) {
    std::fprintf(stderr, "PyTorch baseline failed: %s\n", command.c_str());
    return 0.0;
  }
  return value;
}

// Microseconds of one DynamicsModel::predict call for `envs` environments.
double predict_microseconds(Architecture kind, const Settings& s, int envs) {
  Model model(description(kind, s), 0);
  const envs::BatchMatrix windows = envs::BatchMatrix::Random(envs, s.window * 6) * 10.0f;
  envs::BatchMatrix next;
  for (int i = 0; i < 5; ++i) model.predict(windows, next);
  const int calls = std::max(20, 400 / envs);
  std::vector<double> times;
  for (int r = 0; r < 5; ++r) {
    const double start = thread_seconds();
    for (int i = 0; i < calls; ++i) model.predict(windows, next);
    times.push_back(1e6 * (thread_seconds() - start) / calls);
  }
  return median(times);
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  const std::map<std::string, int*> integers{{"--hidden", &s.hidden},  {"--layers", &s.layers},
                                             {"--heads", &s.heads},    {"--window", &s.window},
                                             {"--batch", &s.batch},    {"--batches", &s.batches},
                                             {"--repeats", &s.repeats}};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--python") {
      s.python = argv[i + 1];
    } else if (integers.count(flag)) {
      *integers.at(flag) = std::stoi(argv[i + 1]);
    } else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  dynamics::use_one_torch_thread();
  std::printf(
      "training throughput, hidden %d x %d layers, window %d, batch %d, %d batches, "
      "1 thread, median batch time, best of %d alternating runs\n",
      s.hidden, s.layers, s.window, s.batch, s.batches, s.repeats);
  std::printf("%-20s %16s %16s %8s\n", "model", "tendril win/s", "PyTorch win/s", "ratio");
  for (Architecture kind : {Architecture::kLstm, Architecture::kSeq2SeqAttention}) {
    std::vector<double> ours, theirs;
    for (int r = 0; r < s.repeats; ++r) {
      ours.push_back(tendril_windows_per_second(kind, s));
      theirs.push_back(pytorch_windows_per_second(kind, s));
    }
    const double a = *std::max_element(ours.begin(), ours.end());
    const double b = *std::max_element(theirs.begin(), theirs.end());
    std::printf("%-20s %16.1f %16.1f %8.2f\n", architecture_name(kind).c_str(), a, b,
                b > 0 ? a / b : 0.0);
    std::fflush(stdout);
  }
  std::printf("\nbatched prediction (DynamicsModel::predict), microseconds\n");
  std::printf("%-20s %14s %14s %18s\n", "model", "N=1 per step", "N=16 per step",
              "N=16 per env step");
  for (Architecture kind : {Architecture::kLstm, Architecture::kSeq2SeqAttention}) {
    const double one = predict_microseconds(kind, s, 1);
    const double sixteen = predict_microseconds(kind, s, 16);
    std::printf("%-20s %14.1f %14.1f %18.1f\n", architecture_name(kind).c_str(), one, sixteen,
                sixteen / 16.0);
    std::fflush(stdout);
  }
  return 0;
}
