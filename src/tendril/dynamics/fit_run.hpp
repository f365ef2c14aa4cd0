#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/dynamics/architecture.hpp"
#include "tendril/dynamics/evaluation.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/dynamics/prepared_csv.hpp"
#include "tendril/dynamics/trainer.hpp"

namespace tendril::dynamics {

// One model-fitting experiment file (`tendril model fit`):
//
//   data:
//     file: data/sma_limb/stiff_exploration_prepared.csv  # a prepared data set (prepared_csv.hpp)
//     state_columns: [theta_x, theta_y, omega_x, omega_y]
//     input_columns: [u_x, u_y]
//     max_gap_s: 0                       # a longer pause starts a new segment; 0: 5 periods
//   model: {...}                         # ArchitectureSpec; absent when fine-tuning
//   init_from: runs/stiff_lstm-…         # fine-tune: start from this model (file or run)
//   training: {...}                      # TrainingOptions
//   evaluation:
//     horizons_s: [60, 1800]             # recursive rollouts after fitting, on the test split
//   seed: 1
//   output: runs/dynamics_lstm           # where new runs go (a timestamp is appended)
//
// Relative paths are taken from the working directory. Every key is checked.
struct FitExperiment {
  Config config;
  std::filesystem::path data_file;
  CsvColumns columns;
  double max_gap = 0.0;
  std::optional<Config> model;  // the `model:` mapping, unless fine-tuning
  std::filesystem::path init_from;
  TrainingOptions training;
  std::vector<double> horizons;
  uint64_t seed = 1;
  std::string output;

  static FitExperiment from_config(Config config);
};

struct EvaluationRow {
  std::string metric;    // "one_step" or "rollout"
  double horizon = 0.0;  // seconds (0 for one-step)
  ErrorReport errors;
};

struct FitResult {
  std::filesystem::path run_directory;
  TrainingReport training;
  int64_t parameters = 0;
  std::vector<EvaluationRow> evaluation;  // on the test split, when the data has one
};

// Fits a model into a new run directory (`run_directory` must not exist or be empty; nothing is
// overwritten): config.yaml (with overrides), progress.csv and TensorBoard events (one row per
// epoch), model.tdm (the best model so far, replaced as validation improves) and, after
// fitting, evaluation.csv (one-step and rollout RMSE on the test split).
// Ctrl-C or SIGTERM (after core/interrupt.hpp's catch_interrupts) stops the fit at the end of an
// epoch with a checkpoint (fit.ckpt; the result's training.interrupted names the signal) and
// without the evaluation; resume_fit continues it to exactly the uninterrupted fit's files.
FitResult run_fit(const FitExperiment& experiment, const std::filesystem::path& run_directory,
                  bool quiet = false);
// Whether `run_directory` holds a fit stopped with a checkpoint.
bool is_stopped_fit(const std::filesystem::path& run_directory);
// Continues a stopped fit in its run directory with the config.yaml written there (a relative
// data file is found from the working directory, as when the fit began).
FitResult resume_fit(const std::filesystem::path& run_directory, bool quiet = false);

// What watches an evaluation: each row as soon as it is measured (long rollouts take a while),
// and the share done of the row being measured (metric and horizon as its row will name them).
struct EvaluationObserver {
  std::function<void(const EvaluationRow&)> on_row;
  std::function<void(const std::string& metric, double horizon, double done)> on_progress;
};

// One-step errors and rollouts of every horizon on `split` of `data` (rows in the order given).
std::vector<EvaluationRow> evaluate_model(Model& model, const SequenceData& data, Split split,
                                          const std::vector<double>& horizons, double max_gap,
                                          const EvaluationObserver& observer = {});

// Writes rows as CSV (metric,horizon_s,group,unit,rmse,points,rollouts), atomically; raises
// Error if `file` exists.
void write_evaluation_csv(const std::vector<EvaluationRow>& rows,
                          const std::filesystem::path& file);

// The gap that separates segments: `configured`, or 5 sampling periods when it is 0.
double segment_gap(const SequenceData& data, double configured);

}  // namespace tendril::dynamics
