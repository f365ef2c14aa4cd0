#include "tendril/sweeps/runs_report.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

namespace tendril::sweeps {

namespace {

std::string fixed(double value, const char* format = "%.2f") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// "mean ± std" of a spread over `runs` runs, "(k of n runs)" added when some runs gave no value.
std::string spread_cell(const Spread& s, std::size_t runs) {
  if (s.count == 0) return "–";
  std::string cell = fixed(s.mean) + " ± " + fixed(s.std);
  if (static_cast<std::size_t>(s.count) < runs) {
    cell += " (" + std::to_string(s.count) + " of " + std::to_string(runs) + " runs)";
  }
  return cell;
}

// The spread of the values present.
Spread spread_of_present(const std::vector<std::optional<double>>& values) {
  std::vector<double> present;
  for (const auto& value : values) {
    if (value) present.push_back(*value);
  }
  return spread_of(present);
}

std::string value_cell(const std::optional<double>& value) { return value ? fixed(*value) : "–"; }

std::optional<double> training_mean_at_end(const RunSummary& run) {
  if (run.train.y.empty()) return std::nullopt;
  return run.train.y.back();
}

std::string header(const std::string& first, const std::vector<double>& steps,
                   const std::vector<std::string>& last) {
  std::string row = "| " + first + " |";
  for (const double step : steps) row += " training mean at " + fixed(step, "%.0f") + " |";
  row += " training mean at the end |";
  for (const std::string& column : last) row += " " + column + " |";
  row += "\n|---|";
  for (std::size_t k = 0; k < steps.size() + 1 + last.size(); ++k) row += "---|";
  return row + "\n";
}

}  // namespace

std::string runs_report(const SweepSummary& summary, const std::vector<double>& steps) {
  int finished = 0;
  for (const RunSummary& run : summary.runs) finished += run.finished;
  std::string page = "# Runs\n\n" + std::to_string(summary.runs.size()) + " runs (" +
                     std::to_string(finished) + " finished) in " +
                     std::to_string(summary.configurations.size()) +
                     " configurations (runs whose names differ only by their seed token); "
                     "training time summed over runs " +
                     fixed(summary.run_seconds, "%.1f") + " s (" +
                     fixed(summary.run_seconds / 3600.0) + " h).\n\n";
  page +=
      "Training mean: rollout/ep_rew_mean (the mean return of the last 100 training episodes) "
      "in a run's last progress.csv row at or before the step, or its last row; final "
      "evaluation: the last row of a finished run's eval.csv. Configurations give the mean ± "
      "population standard deviation over their runs.\n\n## Configurations\n\n";
  page += header("configuration", steps, {"final evaluation", "runs", "training time (s)"});
  for (const ConfigurationSummary& c : summary.configurations) {
    std::vector<std::optional<double>> at_end;
    std::vector<std::vector<std::optional<double>>> at(steps.size());
    double seconds = 0.0;
    for (const int i : c.runs) {
      const RunSummary& run = summary.runs[i];
      for (std::size_t k = 0; k < steps.size(); ++k) {
        at[k].push_back(training_mean_at(run, steps[k]));
      }
      at_end.push_back(training_mean_at_end(run));
      seconds += run.seconds;
    }
    const std::size_t runs = c.runs.size();
    page += "| " + c.name + " |";
    for (const auto& values : at) page += " " + spread_cell(spread_of_present(values), runs) + " |";
    page += " " + spread_cell(spread_of_present(at_end), runs) + " | " +
            spread_cell(c.final_eval, runs) + " | " + std::to_string(runs) + " | " +
            fixed(seconds, "%.1f") + " |\n";
  }
  page += "\n## Runs\n\n";
  page += header(
      "run", steps,
      {"final evaluation (mean ± std of its episodes)", "steps", "training time (s)", "steps/s"});
  for (const RunSummary& run : summary.runs) {
    page += "| " + run.name + " |";
    for (const double step : steps) page += " " + value_cell(training_mean_at(run, step)) + " |";
    const std::string final_eval = run.finished && run.final_eval_mean
                                       ? fixed(*run.final_eval_mean) + " ± " +
                                             fixed(run.final_eval_std.value_or(NAN)) + " at " +
                                             std::to_string(run.final_eval_steps)
                                       : "–";
    page += " " + value_cell(training_mean_at_end(run)) + " | " + final_eval + " | " +
            std::to_string(run.steps) + " | " + fixed(run.seconds, "%.1f") + " | " +
            fixed(run.steps_per_second, "%.0f") + " |\n";
  }
  return page;
}

}  // namespace tendril::sweeps
