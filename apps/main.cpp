// tendril — simulate soft robots, train controllers for them, learn models of them, keep them
// safe and adapt controllers to the real robot. The commands live in command_table.cpp.
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/numerics_mode.hpp"
#ifdef TENDRIL_WITH_RL
#include "tendril/nn/threads.hpp"
#endif
#ifdef TENDRIL_WITH_DYNAMICS
#include "dynamics_plugin.hpp"
#include "tendril/core/dynamics_layer.hpp"
#endif

int main(int argc, char** argv) {
  // A portable build runs with its numerical libraries' kernels pinned (docs/reproducibility.md).
  try {
    tendril::pin_portable_kernels(argv);
  } catch (const tendril::Error& e) {
    std::fprintf(stderr, "tendril: error: %s\n", e.what());
    return 1;
  }
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "--version") {
    std::printf("tendril %s\n%s\n", tendril::tendril_version().c_str(),
                tendril::numerics_description().c_str());
    return 0;
  }
  // A closed output pipe (`tendril train ... | head`) or a file-size limit makes writes fail
  // with an error that names the file, instead of ending the process mid-run.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
#ifdef TENDRIL_WITH_RL
  // One BLAS thread unless an algorithm scopes more: the other core steps environments.
  tendril::nn::configure_numerics(1);
#endif
#ifdef TENDRIL_WITH_DYNAMICS
  // Environments around learned models (opened from their `model` parameter) and policies with
  // a learned-model head (seed 001 ch. 5) load the dynamics plugin, and LibTorch with it, when
  // the first of them is made: commands without learned models start without it.
  tendril::set_dynamics_layer_loader([] { tendril::apps::dynamics_plugin().install(); });
#endif
  return tendril::apps::run_command_line(tendril::apps::command_table(), args);
}
