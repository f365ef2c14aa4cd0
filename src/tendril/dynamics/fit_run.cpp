#include "tendril/dynamics/fit_run.hpp"

#include <charconv>
#include <cstdio>
#include <functional>
#include <limits>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/core/run_lock.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/dynamics/evaluation_progress.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/dynamics/torch_threads.hpp"
#include "tendril/dynamics/trainer.hpp"
#include "tendril/dynamics/window_set.hpp"

namespace tendril::dynamics {

namespace {

namespace fs = std::filesystem;

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

std::string exact(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// A model for `data`: the experiment's architecture with normalisation fitted on the data's
// train rows, or the model to fine-tune, which keeps its own normalisation.
std::unique_ptr<Model> initial_model(const FitExperiment& e, const SequenceData& data) {
  if (!e.init_from.empty()) {
    std::unique_ptr<Model> model = load_model(e.init_from);
    const ModelDescription& d = model->description();
    require(d.state_names == data.state_names && d.input_names == data.input_names,
            "the model to fine-tune reads other columns than the data's", e.init_from.string());
    return model;
  }
  ModelDescription d;
  d.architecture = ArchitectureSpec::from_config(*e.model, data.state_dim(), data.input_dim());
  d.normalizer = Normalizer::fit(data, d.architecture.normalization);
  d.state_names = data.state_names;
  d.input_names = data.input_names;
  d.sample_period = data.sample_period();
  return std::make_unique<Model>(d, e.seed);
}

}  // namespace

double segment_gap(const SequenceData& data, double configured) {
  return configured > 0.0 ? configured : 5.0 * data.sample_period();
}

FitExperiment FitExperiment::from_config(Config config) {
  expect_kind(config, file_kind::kModelFit);
  FitExperiment e;
  e.config = config;
  const Config data = config.child("data");
  e.data_file = data.get<std::string>("file");
  e.columns.states = data.get_or<std::vector<std::string>>("state_columns", e.columns.states);
  e.columns.inputs = data.get_or<std::vector<std::string>>("input_columns", e.columns.inputs);
  e.max_gap = data.get_or<double>("max_gap_s", 0.0);
  require(e.max_gap >= 0.0, "must not be negative", key(data, "max_gap_s"));
  e.init_from = config.get_or<std::string>("init_from", "");
  if (config.has("model")) {
    require(e.init_from.empty(),
            "fine-tuning keeps the architecture of init_from's model; remove model:",
            key(config, "model"));
    e.model = config.child("model");
    // Sizes come from the data; check every other key now.
    ArchitectureSpec::from_config(*e.model, static_cast<int>(e.columns.states.size()),
                                  static_cast<int>(e.columns.inputs.size()));
  } else {
    require(!e.init_from.empty(), "needs model: (or init_from: to fine-tune)",
            key(config, "model"));
  }
  e.training = TrainingOptions::from_config(config.child("training"));
  e.horizons = config.child("evaluation").get_or<std::vector<double>>("horizons_s", {60.0, 1800.0});
  for (double horizon : e.horizons) {
    require(horizon > 0.0, "horizons must be positive", key(config, "evaluation.horizons_s"));
  }
  e.seed = config.get_or<uint64_t>("seed", 1);
  e.output = config.get_or<std::string>("output", "runs/dynamics");
  config.reject_unknown();
  return e;
}

std::vector<EvaluationRow> evaluate_model(Model& model, const SequenceData& data, Split split,
                                          const std::vector<double>& horizons, double max_gap,
                                          const EvaluationObserver& observer) {
  const auto progress_of = [&observer](const std::string& metric, double horizon) -> Progress {
    if (!observer.on_progress) return {};
    return
        [&observer, metric, horizon](double done) { observer.on_progress(metric, horizon, done); };
  };
  std::vector<EvaluationRow> rows;
  const WindowSet windows(data, model, max_gap);
  rows.push_back({"one_step", 0.0,
                  one_step_errors(model, windows, split, 256, {}, progress_of("one_step", 0.0))});
  if (observer.on_row) observer.on_row(rows.back());
  for (double horizon : horizons) {
    rows.push_back(
        {"rollout", horizon,
         rollout_errors(model, data, split, horizon, max_gap, progress_of("rollout", horizon))});
    if (observer.on_row) observer.on_row(rows.back());
  }
  return rows;
}

void write_evaluation_csv(const std::vector<EvaluationRow>& rows, const fs::path& file) {
  require(!fs::exists(file), "exists; nothing is overwritten", file.string());
  std::string out = "metric,horizon_s,group,unit,rmse,points,rollouts\n";
  for (const EvaluationRow& row : rows) {
    for (std::size_t g = 0; g < row.errors.groups.size(); ++g) {
      out += row.metric + "," + exact(row.horizon) + "," + row.errors.groups[g].name + "," +
             row.errors.groups[g].unit + "," + exact(row.errors.rmse[g]) + "," +
             std::to_string(row.errors.points) + "," + std::to_string(row.errors.rollouts) + "\n";
    }
  }
  write_file_atomically(file, out, "evaluation");
}

namespace {

// A fit into `run_directory`: a new one, or (resuming) the continuation of the one its
// checkpoint holds.
FitResult fit(const FitExperiment& e, const fs::path& run_directory, bool quiet, bool resuming) {
  dynamics::use_one_torch_thread();
  const fs::path checkpoint = run_directory / kFitCheckpointName;
  const SequenceData data = read_prepared_csv(e.data_file, e.columns);
  const double max_gap = segment_gap(data, e.max_gap);
  std::unique_ptr<Model> model = initial_model(e, data);
  const WindowSet windows(data, *model, max_gap);
  // A window is `window` rows and the row after them, all in one segment.
  require(e.training.epochs == 0 || !windows.ends(Split::kTrain).empty(),
          "no training window fits: " +
              data.describe_runs(Split::kTrain, model->spec().window + 1, max_gap),
          data.source);

  if (!resuming) fs::create_directories(run_directory);
  // Held while fitting: the dashboard shows the fit as running while a process holds it.
  const RunLock lock(run_directory);
  if (resuming) {
    require(fs::exists(checkpoint),
            "has no fit checkpoint to continue from (a fit writes one only when stopped by "
            "Ctrl-C or SIGTERM; a finished fit has none)",
            run_directory.string());
  } else {
    write_run_record(run_directory, e.config.dump_resolved());
  }
  // Resuming drops log rows of epochs after the checkpoint (none, unless a kill came later).
  ScalarLog log(run_directory, resuming,
                resuming ? checkpoint_epochs(checkpoint) : std::numeric_limits<int64_t>::max());
  const fs::path model_file = run_directory / kModelFileName;
  FitResult result;
  result.run_directory = run_directory;
  for (const auto& parameter : model->network().parameters())
    result.parameters += parameter.numel();
  result.training = train_model(
      *model, windows, e.training, e.seed,
      [&](const EpochReport& epoch) {
        log.record("train/loss", epoch.train_loss);
        if (!std::isnan(epoch.validation_loss)) log.record("train/val_loss", epoch.validation_loss);
        log.record("train/learning_rate", epoch.learning_rate);
        log.record("time/epochs", epoch.epoch);
        log.record("time/windows", static_cast<double>(epoch.windows));
        log.record("time/fps", static_cast<double>(epoch.windows) / std::max(epoch.seconds, 1e-9));
        log.record("time/time_elapsed", epoch.seconds);
        log.dump(epoch.epoch);
        if (epoch.improved) save_model(*model, model_file, /*replace=*/true);
      },
      quiet, checkpoint);
  if (result.training.interrupted != 0) return result;  // the checkpoint holds the fit
  if (fs::exists(checkpoint)) fs::remove(checkpoint);   // finished: nothing left to continue
  // Zero epochs (evaluating a model to fine-tune as it is) still leave a model file.
  if (!fs::exists(model_file)) save_model(*model, model_file);
  if (!windows.ends(Split::kTest).empty()) {
    if (!quiet) {
      std::fprintf(stderr,
                   "evaluating the model on the test split: one-step errors and %zu "
                   "rollout horizons...\n",
                   e.horizons.size());
    }
    EvaluationProgress progress;
    EvaluationObserver observer;
    if (!quiet) observer.on_progress = std::ref(progress);
    result.evaluation = evaluate_model(*model, data, Split::kTest, e.horizons, max_gap, observer);
    progress.finish();
    write_evaluation_csv(result.evaluation, run_directory / "evaluation.csv");
  }
  return result;
}

}  // namespace

FitResult run_fit(const FitExperiment& e, const fs::path& run_directory, bool quiet) {
  require(!fs::exists(run_directory) || fs::is_empty(run_directory),
          "run directory exists and is not empty; nothing is overwritten", run_directory.string());
  return fit(e, run_directory, quiet, /*resuming=*/false);
}

bool is_stopped_fit(const fs::path& run_directory) {
  return fs::exists(run_directory / kFitCheckpointName);
}

FitResult resume_fit(const fs::path& run_directory, bool quiet) {
  return fit(FitExperiment::from_config(load_run_config(run_directory)), run_directory, quiet,
             /*resuming=*/true);
}

}  // namespace tendril::dynamics
