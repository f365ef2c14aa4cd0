#pragma once

#include <filesystem>
#include <functional>

#include "tendril/core/config.hpp"
#include "tendril/rl/observer.hpp"
#include "tendril/rl/training_observers.hpp"

namespace tendril::safety {

// Creates a safety run's directory, which must not exist or be empty (nothing is overwritten),
// and writes the experiment into it as config.yaml.
void start_run_directory(const std::filesystem::path& run_directory, const Config& experiment);

// progress.csv and the TensorBoard event file of a safety run: the task agent's scalars as the
// trainer logs them (rl::ScalarLogObserver, Stable-Baselines3's names) plus those `extra`
// appends at each iteration (the safety agent's, a multiplier).
class RunScalarLog : public rl::Observer {
 public:
  RunScalarLog(const std::filesystem::path& run_directory,
               std::function<void(rl::TrainStats&)> extra);
  bool on_iteration(const rl::Progress& progress) override;

 private:
  rl::ScalarLogObserver log_;
  std::function<void(rl::TrainStats&)> extra_;
};

}  // namespace tendril::safety
