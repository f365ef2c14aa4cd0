#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/config.hpp"

namespace tendril::sweeps {

// A grid of runs of one experiment, e.g. a batch-size study over five seeds:
//
//   experiment: ../tracking3d_ppo.yaml      # relative to this file
//   grid:                                   # the Cartesian product, the first key varying slowest
//     - {key: algo.n_steps, values: [256, 512, 1024]}
//     - {key: seed, values: [0, 1, 2, 3, 4]}
//   output: runs/sweeps/tracking3d_ppo_batch
//
// Run i is the experiment with its overrides (as `--set key=value`), trained into
// <output>/<key>_<value>-… (the last part of each key). Unknown keys raise Error naming the key.
struct Sweep {
  struct Run {
    std::string name;
    std::vector<std::pair<std::string, std::string>> overrides;
  };

  std::filesystem::path experiment_file;
  std::vector<std::pair<std::string, std::vector<std::string>>> grid;
  std::string output;

  static Sweep load(const std::filesystem::path& file);
  std::vector<Run> runs() const;
  // <output>/<run name>
  std::filesystem::path directory(const Run& run) const;
  // The experiment of run `run`, every key checked.
  Config experiment(const Run& run) const;
};

}  // namespace tendril::sweeps
