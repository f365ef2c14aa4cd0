#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tendril/rl/experiment.hpp"
#include "tendril/rl/run_companion.hpp"

namespace tendril::rl {

// Runs an experiment into a run directory (DESIGN.md, "Experiments and runs"):
//   config.yaml       the experiment with overrides applied
//   progress.csv      one row per iteration, Stable-Baselines3's column names
//   events.out.tfevents.*   the same scalars for TensorBoard
//   eval.csv          evaluation returns every `eval.freq` steps and at the end
//   checkpoints/step_<N>.ckpt   everything needed to resume, every `checkpoint_freq` steps and
//                     at the end (the source of a warm start)
//   model.policy      the final policy (rl::load_policy; acts on raw observations)
//   best_model.policy with eval.save_best: the policy of the best evaluation (highest mean
//                     return; the latest of equals, which has trained longest)
//   run.lock          held (core/run_lock) by the one process that writes the run
// and a live progress line on standard error.
//
// Faults: config.yaml and the CSV headers are written atomically before training starts;
// every write is checked (a full disk raises Error naming the file); after SIGINT/SIGTERM
// (core/interrupt, when the program catches them) the run writes a checkpoint at the end of
// the current iteration and returns with `interrupted` set. A resumed run drops the log rows
// written after its checkpoint, so its logs hold one timeline, and removes the temporary files
// of writes its predecessor did not finish.
struct TrainOptions {
  // Stop after the first checkpoint at or past this many steps (a run paused on purpose; it
  // continues with `resume`). Unset: train to n_timesteps.
  std::optional<int64_t> stop_at;
  bool quiet = false;  // no progress line
  // Where the progress line goes (standard error when unset), e.g. Python's sys.stderr.
  std::function<void(const std::string&)> progress_output = nullptr;
  // Called after every iteration with its progress (a monitor; it cannot stop the run).
  std::function<void(const Progress&)> on_iteration = nullptr;
  // `train` into a directory that holds an earlier start of the same experiment (the same
  // config.yaml) that never reached a checkpoint: start it again instead of refusing.
  bool restart_unstarted = false;
  // What trains beside the algorithm from its steps (a co-trained safety agent, a cost
  // critic); made once per process, carried in every checkpoint. None when unset.
  CompanionFactory companion = nullptr;
};

struct TrainResult {
  std::filesystem::path run_directory;
  int64_t timesteps = 0;
  bool finished = false;         // reached n_timesteps
  double final_eval_mean = 0.0;  // of the last evaluation (when finished)
  double final_eval_std = 0.0;
  std::optional<double> best_eval_mean;  // with eval.save_best: of best_model.policy
  int64_t best_eval_timesteps = 0;
  double seconds = 0.0;
  double steps_per_second = 0.0;
  int interrupted = 0;  // the signal that stopped the run early (a checkpoint holds its state)
  TrainStats companion_scalars;  // the companion's scalars at the end (RunCompanion::add_scalars)
};

// The directory a run of `experiment` gets when none is named: <output>-seed<N>-<time stamp>, so
// that runs of one experiment that differ only by seed group together (seed_group).
std::filesystem::path default_run_directory(const Experiment& experiment);

// Starts a run in `run_directory`, which must not exist or be empty (nothing is overwritten).
// Raises Error naming the holder when another process holds the directory.
TrainResult train(const Experiment& experiment, const std::filesystem::path& run_directory,
                  const TrainOptions& options = {});

// Continues the run in `run_directory` from its newest checkpoint, with the experiment saved
// there. The resumed run computes exactly what the uninterrupted run computes: checkpoints are
// taken between iterations and hold the environments' state when they support snapshots (and
// otherwise every environment restarts from a seeded reset after each checkpoint).
// A corrupt or truncated newest checkpoint is reported (log warning naming it), renamed to
// `step_<N>.ckpt.corrupt`, and the newest intact one is used. A finished run (model.policy
// present) is refused and left unchanged.
TrainResult resume(const std::filesystem::path& run_directory, const TrainOptions& options = {});
// The same with the run's experiment already read (load_run_config, then whatever reads the
// sections Experiment does not know, e.g. a co-trained safety agent's).
TrainResult resume(const std::filesystem::path& run_directory, const Experiment& experiment,
                   const TrainOptions& options);

// A run's config.yaml, its checksum verified, with `overrides` (key=value) applied.
Config load_run_config(const std::filesystem::path& run_directory,
                       const std::vector<std::pair<std::string, std::string>>& overrides = {});

// The experiment of a run, from its config.yaml (which ends with a comment holding its CRC-32C:
// a damaged or edited file raises Error instead of resuming or evaluating another experiment).
// `overrides` (key=value, as --set gives them) change it for this use, e.g. the environment's
// parameters to test a policy on conditions it was not trained on.
Experiment load_run_experiment(
    const std::filesystem::path& run_directory,
    const std::vector<std::pair<std::string, std::string>>& overrides = {});

// The newest checkpoint in a run directory; raises Error if there is none.
std::filesystem::path latest_checkpoint(const std::filesystem::path& run_directory);
// The checkpoints of a run directory, newest first.
std::vector<std::filesystem::path> checkpoints(const std::filesystem::path& run_directory);
// The newest checkpoint for which `use` (e.g. verifying or loading it) does not raise Error;
// `skipped` receives each newer one's reason ("<file>: <reason>"). Raises Error listing every
// reason when none is usable, or when there is no checkpoint.
std::filesystem::path newest_usable_checkpoint(
    const std::filesystem::path& run_directory,
    const std::function<void(const std::filesystem::path&)>& use,
    std::vector<std::string>* skipped = nullptr);
// The newest checkpoint whose archive verifies (core/archive).
std::filesystem::path newest_intact_checkpoint(const std::filesystem::path& run_directory,
                                               std::vector<std::string>* skipped = nullptr);

}  // namespace tendril::rl
