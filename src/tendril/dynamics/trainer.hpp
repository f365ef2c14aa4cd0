#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

#include "tendril/core/config.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/window_set.hpp"

namespace tendril::dynamics {

// How a dynamics model is fitted (seed 001 §4.3.2 and [CODE]; seed 002 §III-C):
//
//   training:
//     epochs: 400
//     batch_size: 1024
//     learning_rate: 1.0e-3       # Adam
//     final_learning_rate: 1.0e-3 # lr falls geometrically per epoch to this (seed 002: 1e-4)
//     grad_clip_value: 1.0        # every gradient entry clipped to ±this; 0: none
//     validation_fraction: 0.1    # the latest train windows, held out for early stopping
//     patience: 0                 # epochs without a better validation loss before stopping; 0:
//     never windows_per_epoch: 0        # a random subset of this many train windows per epoch; 0:
//     all
struct TrainingOptions {
  int epochs = 400;
  int batch_size = 1024;
  double learning_rate = 1e-3;
  double final_learning_rate = 1e-3;
  double grad_clip_value = 1.0;
  double validation_fraction = 0.1;
  int patience = 0;
  int64_t windows_per_epoch = 0;

  static TrainingOptions from_config(const Config& training);
  // The learning rate of epoch `epoch` (0-based): lr₀ · (lr_final / lr₀)^(epoch / (epochs − 1)).
  double learning_rate_at(int epoch) const;
};

struct EpochReport {
  int epoch = 0;                 // 1-based
  double train_loss = 0.0;       // mean MSE of the epoch's batches
  double validation_loss = 0.0;  // MSE over the validation windows (NaN without validation)
  double learning_rate = 0.0;
  int64_t windows = 0;  // trained so far
  double seconds = 0.0;
  bool improved = false;  // the best validation loss so far; the model now holds these weights
};

struct TrainingReport {
  int epochs_run = 0;
  int best_epoch = 0;
  double best_validation_loss = 0.0;
  double final_train_loss = 0.0;
  bool stopped_early = false;
  double seconds = 0.0;
  double windows_per_second = 0.0;
  int64_t train_windows = 0;
  int64_t validation_windows = 0;
  int interrupted = 0;  // the signal that stopped the fit at an epoch's end (a checkpoint holds it)
};

// Fits `model` on the train windows of `windows` with Adam on the MSE of the network's output
// (thesis eq. 4.8), gradient-value clipping, windows shuffled every epoch from Rng(seed) and a
// learning rate falling per epoch. After each epoch `on_epoch` sees the report — with
// `improved` set, the model holds the best weights so far (the caller may save them). At the
// end the model holds the weights of the best validation loss (or the last epoch's without a
// validation split). Prints a progress line with ETA on standard error unless `quiet`.
//
// With a `checkpoint_file`, a SIGINT or SIGTERM caught meanwhile (core/interrupt.hpp) stops the
// fit at the end of the current epoch: everything the later epochs need (weights, Adam's state,
// the random streams, the shuffled order, the best weights and the report so far) goes to that
// file and the report says `interrupted`. When the file exists at the start, the fit continues
// from it and computes exactly what the uninterrupted fit computes.
TrainingReport train_model(Model& model, const WindowSet& windows, const TrainingOptions& options,
                           uint64_t seed, const std::function<void(const EpochReport&)>& on_epoch,
                           bool quiet = false, const std::filesystem::path& checkpoint_file = {});

// The epochs a fit checkpoint of train_model holds (the last epoch its fit logged).
int checkpoint_epochs(const std::filesystem::path& checkpoint_file);

}  // namespace tendril::dynamics
