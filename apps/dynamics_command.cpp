// `tendril model fit`, `tendril model eval` and the continuation of a stopped fit: fit learned
// dynamics models and measure how well they predict. Part of the dynamics plugin
// (dynamics_plugin.hpp), which the program loads when one of them runs.
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "dynamics_plugin.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/dynamics/evaluation.hpp"
#include "tendril/dynamics/evaluation_progress.hpp"
#include "tendril/dynamics/fit_run.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/dynamics/open_loop.hpp"
#include "tendril/dynamics/torch_threads.hpp"
#include "tendril/envs/sma_limb/open_loop_inputs.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;
using namespace tendril::dynamics;

void print_row(const EvaluationRow& row) {
  std::string label = row.metric == "one_step" ? "one-step" : row.metric;
  if (row.metric.find("rollout") != std::string::npos) {
    char horizon[48];
    std::snprintf(horizon, sizeof horizon, " %gs", row.horizon);
    label += horizon;
  }
  std::printf("  %-16s", label.c_str());
  for (std::size_t g = 0; g < row.errors.groups.size(); ++g) {
    std::printf("  RMSE %s %.4g %s", row.errors.groups[g].name.c_str(), row.errors.rmse[g],
                row.errors.groups[g].unit.c_str());
  }
  std::printf("  (%lld points, %lld starts)\n", static_cast<long long>(row.errors.points),
              static_cast<long long>(row.errors.rollouts));
  std::fflush(stdout);
}

// What a fit (or a continued one) did; 128 + the signal when one stopped it.
int report_fit(const FitResult& result) {
  const TrainingReport& t = result.training;
  const std::string run = result.run_directory.string();
  std::printf(
      "%d epochs in %.1f s (%.0f windows/s), %lld parameters, %lld train / %lld "
      "validation windows%s\n",
      t.epochs_run, t.seconds, t.windows_per_second, static_cast<long long>(result.parameters),
      static_cast<long long>(t.train_windows), static_cast<long long>(t.validation_windows),
      t.stopped_early ? " (stopped early)" : "");
  std::printf("best validation loss %.6g at epoch %d\n", t.best_validation_loss, t.best_epoch);
  if (t.interrupted != 0) {
    std::printf("interrupted by %s; a checkpoint after epoch %d holds the fit\n",
                signal_name(t.interrupted), t.epochs_run);
    std::printf("continue with:  tendril resume %s\n", run.c_str());
    return 128 + t.interrupted;
  }
  if (!result.evaluation.empty()) {
    std::printf("test split:\n");
    for (const EvaluationRow& row : result.evaluation) print_row(row);
  }
  std::printf("model:          %s/%s\n", run.c_str(), kModelFileName);
  std::printf("learning curve: %s/progress.csv (TensorBoard: %s)\n", run.c_str(), run.c_str());
  return 0;
}

}  // namespace

int run_model_fit(const Arguments& line) {
  const FitExperiment experiment =
      FitExperiment::from_config(line.load_config(file_kind::kModelFit));
  fs::path run = line.value("output", "");
  if (run.empty()) {
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    run = experiment.output + "-" + stamp;
  }
  std::printf("fitting %s on %s for %d epochs, seed %llu -> %s\n",
              experiment.model ? experiment.model->get<std::string>("architecture").c_str()
                               : ("fine-tune of " + experiment.init_from.string()).c_str(),
              experiment.data_file.string().c_str(), experiment.training.epochs,
              static_cast<unsigned long long>(experiment.seed), run.string().c_str());
  std::fflush(stdout);
  catch_interrupts();  // Ctrl-C: a checkpoint at the end of the epoch; `tendril resume` continues
  return report_fit(run_fit(experiment, run, line.has("quiet")));
}

std::optional<int> continue_stopped_fit(const Arguments& line) {
  const fs::path run = line.positional.front();
  if (!is_stopped_fit(run)) {
    require(!fs::exists(run / kModelFileName),
            "a model fit with nothing to continue: it finished, or was killed without the polite "
            "stop that writes a checkpoint (fit it again)",
            run.string());
    return std::nullopt;
  }
  if (line.has("stop-at")) throw UsageError("--stop-at counts training steps: a fit has none");
  std::printf("continuing the fit in %s\n", run.string().c_str());
  std::fflush(stdout);
  catch_interrupts();
  return report_fit(resume_fit(run, line.has("quiet")));
}

namespace {

const char* const kOpenLoopInputs[] = {"sine", "square", "sawtooth"};

fs::path open_loop_file(const fs::path& directory, const std::string& kind) {
  return directory / ("open_loop_" + kind + ".csv");
}

// The model's open-loop response to the three test inputs from the data's first state, one CSV
// per input in `directory` (the data behind Fig. 4.4's counterpart).
void write_open_loop(Model& model, const SequenceData& data, const fs::path& directory) {
  fs::create_directories(directory);
  const Eigen::VectorXd start = data.states.row(0).transpose();
  for (const std::string kind : kOpenLoopInputs) {
    const fs::path file = open_loop_file(directory, kind);
    const RowMatrixXd inputs = envs::sma_limb::open_loop_inputs(kind, 800);
    const RowMatrixXd states = open_loop_rollout(model, start, inputs);
    std::ostringstream out;
    out.precision(9);
    out << "time_s";
    for (const auto& name : data.state_names) out << "," << name;
    for (const auto& name : data.input_names) out << "," << name;
    out << "\n";
    for (Eigen::Index k = 0; k < states.rows(); ++k) {
      out << static_cast<double>(k) * model.sample_period();
      for (Eigen::Index c = 0; c < states.cols(); ++c) out << "," << states(k, c);
      for (Eigen::Index c = 0; c < inputs.cols(); ++c) {
        out << "," << (k < inputs.rows() ? inputs(k, c) : 0.0);
      }
      out << "\n";
    }
    write_file_atomically(file, out.str(), "open-loop rollout");
    std::printf("open loop %-8s -> %s\n", kind.c_str(), file.string().c_str());
  }
}

// The "predict no change" baseline beside the model's rows, and the one-step errors of both
// split by whether the input changed within the last 3 readings (a limb that rings after a
// throttle change is predictable neither by persistence nor, from noisy rates, by a model).
std::vector<EvaluationRow> baseline_rows(Model& model, const SequenceData& data, Split split,
                                         const std::vector<double>& horizons, double max_gap,
                                         EvaluationProgress& progress) {
  constexpr int kReadings = 3;
  const WindowSet windows(data, model, max_gap);
  const dynamics::PointFilter changing = [&](int64_t t) {
    return dynamics::input_changed_within(data, t, kReadings);
  };
  const dynamics::PointFilter steady = [&](int64_t t) { return !changing(t); };
  std::vector<EvaluationRow> rows;
  rows.push_back(
      {"persistence_one_step", 0.0, dynamics::persistence_one_step_errors(data, windows, split)});
  for (double horizon : horizons) {
    rows.push_back({"persistence_rollout", horizon,
                    dynamics::persistence_rollout_errors(data, split, horizon, max_gap,
                                                         model.window_length())});
  }
  const std::pair<std::string, dynamics::PointFilter> filtered[] = {
      {"one_step_input_change", changing}, {"one_step_steady_input", steady}};
  for (const auto& [metric, include] : filtered) {
    const std::string& name = metric;
    const dynamics::Progress on_progress = [&progress, &name](double done) {
      progress(name, 0.0, done);
    };
    rows.push_back(
        {metric, 0.0, dynamics::one_step_errors(model, windows, split, 256, include, on_progress)});
    progress.finish();
  }
  rows.push_back({"persistence_one_step_input_change", 0.0,
                  dynamics::persistence_one_step_errors(data, windows, split, changing)});
  rows.push_back({"persistence_one_step_steady_input", 0.0,
                  dynamics::persistence_one_step_errors(data, windows, split, steady)});
  return rows;
}

}  // namespace

int run_model_eval(const Arguments& line) {
  require(line.positional.size() == 2, "expected a run directory (or model file) and a data set",
          "command line");
  // Refuse before the work, not after it: nothing is overwritten.
  if (line.has("output")) {
    require(!fs::exists(line.value("output", "")), "exists; nothing is overwritten",
            line.value("output", ""));
  }
  if (line.has("open-loop-dir")) {
    for (const std::string kind : kOpenLoopInputs) {
      const fs::path file = open_loop_file(line.value("open-loop-dir", ""), kind);
      require(!fs::exists(file), "exists; nothing is overwritten", file.string());
    }
  }
  dynamics::use_one_torch_thread();
  std::unique_ptr<Model> model = load_model(line.positional[0]);
  const ModelDescription& d = model->description();
  const SequenceData data = read_prepared_csv(line.positional[1], {d.state_names, d.input_names});
  const std::string split_name = line.value("split", "test");
  require(split_name == "test" || split_name == "train", "--split expects test or train",
          "command line");
  const Split split = split_name == "test" ? Split::kTest : Split::kTrain;
  std::vector<double> horizons = line.numbers("horizons", 1e-9, 1e9);
  if (horizons.empty()) horizons = {60.0, 1800.0};
  const double max_gap = segment_gap(data, line.number("max-gap", 0.0, 0.0, 1e9));
  std::printf("%s (%s, window %d) on the %s split of %s:\n",
              model_file_path(line.positional[0]).string().c_str(),
              architecture_name(model->spec().kind).c_str(), model->spec().window,
              split_name.c_str(), line.positional[1].c_str());
  // Each row as soon as it is measured: the rollouts of long horizons take a while.
  EvaluationProgress progress;
  const EvaluationObserver observer{.on_row =
                                        [&progress](const EvaluationRow& row) {
                                          progress.finish();
                                          print_row(row);
                                        },
                                    .on_progress = std::ref(progress)};
  std::vector<EvaluationRow> rows =
      evaluate_model(*model, data, split, horizons, max_gap, observer);
  if (line.has("baselines")) {
    for (const EvaluationRow& row :
         baseline_rows(*model, data, split, horizons, max_gap, progress)) {
      print_row(row);
      rows.push_back(row);
    }
  }
  if (line.has("output")) {
    write_evaluation_csv(rows, line.value("output", ""));
    std::printf("errors -> %s\n", line.value("output", "").c_str());
  }
  if (line.has("open-loop-dir")) write_open_loop(*model, data, line.value("open-loop-dir", ""));
  return 0;
}

}  // namespace tendril::apps
