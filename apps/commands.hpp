#pragma once

#include <filesystem>
#include <optional>

#include "cli/arguments.hpp"
#include "tendril/core/config.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

// The functions behind the command table (command_table.cpp); each returns the exit status.
int train_command(const Arguments& line);
int resume_command(const Arguments& line);
int run_command(const Arguments& line);
int sweep_run_command(const Arguments& line);
int sweep_list_command(const Arguments& line);
int sweep_summarize_command(const Arguments& line);
int sweep_slurm_command(const Arguments& line);
int report_command(const Arguments& line);
int data_collect_command(const Arguments& line);
int data_calibrate_command(const Arguments& line);
int data_replay_command(const Arguments& line);
int data_coverage_command(const Arguments& line);
int data_open_loop_command(const Arguments& line);
int data_prepare_command(const Arguments& line);
int model_fit_command(const Arguments& line);
// `tendril resume RUN` of a model fit stopped with a checkpoint: the exit status, or nothing
// when RUN holds no such fit (dynamics layer).
std::optional<int> resume_stopped_fit(const Arguments& line);
int model_eval_command(const Arguments& line);
int safety_eval_command(const Arguments& line);
int safety_search_command(const Arguments& line);
int safety_map_command(const Arguments& line);
int safety_diamond_command(const Arguments& line);
int adapt_command(const Arguments& line);
int track_command(const Arguments& line);
int simulate_command(const Arguments& line);
int serve_command(const Arguments& line);
int plot_command(const Arguments& line);
int export_command(const Arguments& line);
int list_envs_command(const Arguments& line);
int list_algorithms_command(const Arguments& line);
int list_wrappers_command(const Arguments& line);
int robot_emulate_command(const Arguments& line);
int robot_check_command(const Arguments& line);

// Safety co-training (an experiment's `safety:` section) and the constrained baselines
// (`constrained:`), which `train` and `resume` hand over: the task run with its companion
// (rl/run_companion), then the finished run's safety evaluation. `output` unset: the default
// run directory.
int safety_train(const Arguments& line, const Config& config, const rl::TrainOptions& options);
int run_safety_training(const Config& config, const std::optional<std::filesystem::path>& output,
                        rl::TrainOptions options, bool resuming);

// How a training run ended, printed; the exit status (0 finished or paused, 128 + the signal
// that stopped it).
int report_training(const rl::TrainResult& result);

// "SIGINT", "SIGTERM": how the interruption of a run is reported.
const char* signal_name(int signal);

}  // namespace tendril::apps
