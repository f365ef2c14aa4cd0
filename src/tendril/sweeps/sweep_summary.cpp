#include "tendril/sweeps/sweep_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"

namespace tendril::sweeps {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The last part of the sweep's output directory (what holds its runs).
std::string sweep_name(const Sweep& sweep) {
  fs::path path = fs::absolute(sweep.output).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();
  return path.filename().string();
}

bool is_seed_key(const std::string& key) { return key.substr(key.rfind('.') + 1) == "seed"; }

std::string number(double value, const char* format = "%.6g") {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string curve_csv(const CurveStats& stats) {
  std::string text = "steps,mean,std,min,max,seeds\n";
  for (std::size_t i = 0; i < stats.x.size(); ++i) {
    text += number(stats.x[i], "%.10g") + "," + number(stats.mean[i], "%.10g") + "," +
            number(stats.std[i], "%.10g") + "," + number(stats.min[i], "%.10g") + "," +
            number(stats.max[i], "%.10g") + "," + std::to_string(stats.curves) + "\n";
  }
  return text;
}

}  // namespace

RunSummary summarize_run(const fs::path& directory) {
  RunSummary run;
  run.directory = directory;
  run.name = directory.filename().string();
  run.finished = fs::exists(directory / "model.policy");
  const auto progress = read_csv_columns(directory / "progress.csv");
  const auto& steps = column_of(progress, "time/total_timesteps");
  const auto& elapsed = column_of(progress, "time/time_elapsed");
  const auto& fps = column_of(progress, "time/fps");
  if (!steps.empty() && std::isfinite(steps.back())) run.steps = static_cast<int64_t>(steps.back());
  // Each process's stretch ends where the clock restarts (a resume) or at the last row.
  double stretch_steps = 0.0;
  for (std::size_t i = 0; i < std::min(elapsed.size(), fps.size()); ++i) {
    const bool last = i + 1 == elapsed.size() || elapsed[i + 1] < elapsed[i];
    if (last && std::isfinite(elapsed[i]) && std::isfinite(fps[i])) {
      run.seconds += elapsed[i];
      stretch_steps += fps[i] * elapsed[i];
    }
  }
  run.steps_per_second = run.seconds > 0.0 ? stretch_steps / run.seconds : kNaN;
  run.train = curve_of(steps, column_of(progress, "rollout/ep_rew_mean"));
  if (!run.train.y.empty()) run.final_train_mean = run.train.y.back();
  const auto evaluations = read_csv_columns(directory / "eval.csv");
  const auto& eval_steps = column_of(evaluations, "timesteps");
  const auto& eval_mean = column_of(evaluations, "mean_return");
  run.eval = curve_of(eval_steps, eval_mean);
  if (!eval_mean.empty()) {
    run.final_eval_mean = eval_mean.back();
    run.final_eval_std = column_of(evaluations, "std_return").empty()
                             ? kNaN
                             : column_of(evaluations, "std_return").back();
    run.final_eval_steps = static_cast<int64_t>(eval_steps.back());
  }
  return run;
}

namespace {

// Adds run `i` of `summary` to the configuration named `group` (a new one, with `settings`, on
// its first run).
void add_to_configuration(SweepSummary& summary, std::size_t i, const std::string& group,
                          const std::vector<std::pair<std::string, std::string>>& settings) {
  auto found = std::find_if(summary.configurations.begin(), summary.configurations.end(),
                            [&](const ConfigurationSummary& c) { return c.name == group; });
  if (found == summary.configurations.end()) {
    ConfigurationSummary configuration;
    configuration.name = group;
    configuration.settings = settings;
    summary.configurations.push_back(configuration);
    found = summary.configurations.end() - 1;
  }
  found->runs.push_back(static_cast<int>(i));
}

// Each configuration's spreads and curves over its runs, and the training time of them all.
void aggregate_configurations(SweepSummary& summary) {
  for (ConfigurationSummary& configuration : summary.configurations) {
    std::vector<double> finals, speeds;
    std::vector<Curve> train, eval;
    for (const int i : configuration.runs) {
      const RunSummary& run = summary.runs[i];
      if (run.finished && run.final_eval_mean) finals.push_back(*run.final_eval_mean);
      if (std::isfinite(run.steps_per_second)) speeds.push_back(run.steps_per_second);
      train.push_back(run.train);
      eval.push_back(run.eval);
    }
    configuration.final_eval = spread_of(finals);
    configuration.steps_per_second = spread_of(speeds);
    configuration.train = aggregate_curves(train);
    configuration.eval = aggregate_curves(eval);
  }
  for (const RunSummary& run : summary.runs) summary.run_seconds += run.seconds;
}

// The wall time, busy time and process counts of sweep_log.csv (one `start` and one `end` row per
// process: event,unix_time,host,pid,...); each start pairs with the next end of its host and PID.
void read_sweep_log(const fs::path& file, SweepSummary& summary) {
  std::ifstream in(file);
  std::map<std::string, double> started;
  std::vector<std::pair<double, double>> intervals;
  double first = kNaN, last = kNaN;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.size() < 4 || (cells[0] != "start" && cells[0] != "end")) continue;
    const double time = std::strtod(cells[1].c_str(), nullptr);
    first = std::fmin(first, time);
    last = std::fmax(last, time);
    const std::string process = cells[2] + "," + cells[3];
    if (cells[0] == "start") {
      ++summary.processes;
      started[process] = time;
    } else if (const auto start = started.find(process); start != started.end()) {
      ++summary.ended_processes;
      intervals.emplace_back(start->second, time);
      started.erase(start);
    }
  }
  summary.wall_seconds = last - first;  // NaN without events
  std::sort(intervals.begin(), intervals.end());
  double covered_to = -std::numeric_limits<double>::infinity();
  for (const auto& [start, end] : intervals) {
    summary.busy_seconds += std::max(0.0, end - std::max(start, covered_to));
    covered_to = std::max(covered_to, end);
  }
}

}  // namespace

SweepSummary summarize_sweep(const Sweep& sweep) {
  SweepSummary summary;
  const std::vector<Sweep::Run> runs = sweep.runs();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    summary.runs.push_back(summarize_run(sweep.directory(runs[i])));
    std::vector<std::pair<std::string, std::string>> settings;
    for (const auto& [key, value] : runs[i].overrides) {
      if (!is_seed_key(key)) settings.emplace_back(key, value);
    }
    add_to_configuration(summary, i, seed_group(runs[i].name, sweep_name(sweep)), settings);
  }
  aggregate_configurations(summary);
  read_sweep_log(fs::path(sweep.output) / "sweep_log.csv", summary);
  return summary;
}

std::vector<fs::path> run_directories(const std::vector<fs::path>& paths) {
  std::vector<fs::path> runs;
  for (const fs::path& path : paths) {
    require(fs::is_directory(path), "is not a directory", path.string());
    if (fs::exists(path / "progress.csv")) {
      runs.push_back(path);
      continue;
    }
    std::vector<fs::path> inside;
    for (const auto& entry : fs::directory_iterator(path)) {
      if (entry.is_directory() && fs::exists(entry.path() / "progress.csv")) {
        inside.push_back(entry.path());
      }
    }
    require(!inside.empty(), "holds no run (a directory with a progress.csv)", path.string());
    std::sort(inside.begin(), inside.end());
    runs.insert(runs.end(), inside.begin(), inside.end());
  }
  return runs;
}

SweepSummary summarize_runs(const std::vector<fs::path>& runs) {
  SweepSummary summary;
  for (const fs::path& run : runs) summary.runs.push_back(summarize_run(run));
  for (const RunGroup& group : group_by_seed(runs)) {
    for (const int i : group.members) add_to_configuration(summary, i, group.name, {});
  }
  aggregate_configurations(summary);
  summary.wall_seconds = kNaN;
  return summary;
}

std::optional<double> training_mean_at(const RunSummary& run, double step) {
  if (static_cast<double>(run.steps) < step) return std::nullopt;
  const auto after = std::upper_bound(run.train.x.begin(), run.train.x.end(), step);
  if (after == run.train.x.begin()) return std::nullopt;
  return run.train.y[static_cast<std::size_t>(after - run.train.x.begin()) - 1];
}

namespace {

// A file name for a configuration's curves: its name with characters other than letters,
// digits, '.', '-', '_' and '=' replaced by '_'.
std::string file_stem(const std::string& name) {
  std::string stem = name;
  for (char& c : stem) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_' &&
        c != '=')
      c = '_';
  }
  return stem;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string joined(std::initializer_list<std::string> parts, const std::string& separator) {
  std::string text;
  for (const std::string& part : parts) {
    if (&part != parts.begin()) text.append(separator);
    text.append(part);
  }
  return text;
}

std::string duration(double seconds) {
  if (!std::isfinite(seconds)) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.1f s (%.2f h)", seconds, seconds / 3600.0);
  return text;
}

}  // namespace

void write_sweep_summary(const Sweep& sweep, const SweepSummary& summary, const fs::path& directory,
                         const std::vector<std::pair<std::string, std::string>>& figures) {
  fs::create_directories(directory / "curves");
  // Every configuration has the same setting keys (the grid's axes but the seed's).
  std::vector<std::string> keys;
  if (!summary.configurations.empty()) {
    for (const auto& [key, value] : summary.configurations.front().settings) keys.push_back(key);
  }
  std::string configurations = "configuration";
  for (const std::string& key : keys) configurations.append(",").append(csv_cell(key));
  configurations +=
      ",seeds,finished,final_eval_mean,final_eval_std,final_eval_min,final_eval_max,"
      "steps_per_second_mean\n";
  std::string table = "| configuration |";
  for (const std::string& key : keys) table += " " + key + " |";
  table +=
      " finished / seeds | final evaluation, mean ± std over seeds | min | max |"
      " steps/s |\n|---|";
  for (std::size_t k = 0; k < keys.size(); ++k) table += "---|";
  table += "---|---|---|---|---|\n";
  for (const ConfigurationSummary& c : summary.configurations) {
    configurations += csv_cell(c.name);
    table += "| " + c.name + " |";
    for (const auto& [key, value] : c.settings) {
      configurations.append(",").append(csv_cell(value));
      table += " " + value + " |";
    }
    const Spread& f = c.final_eval;
    configurations +=
        joined({"", std::to_string(c.runs.size()), std::to_string(f.count), number(f.mean, "%.10g"),
                number(f.std, "%.10g"), number(f.min, "%.10g"), number(f.max, "%.10g"),
                number(c.steps_per_second.mean, "%.10g")},
               ",") +
        "\n";
    const std::string final_eval =
        f.count ? number(f.mean, "%.2f") + " ± " + number(f.std, "%.2f") : "–";
    table.append(" ")
        .append(joined(
            {std::to_string(f.count) + " / " + std::to_string(c.runs.size()), final_eval,
             number(f.min, "%.2f"), number(f.max, "%.2f"), number(c.steps_per_second.mean, "%.0f")},
            " | "))
        .append(" |\n");
    write_file_atomically(directory / "curves" / (file_stem(c.name) + ".train.csv"),
                          curve_csv(c.train), "learning curve");
    write_file_atomically(directory / "curves" / (file_stem(c.name) + ".eval.csv"),
                          curve_csv(c.eval), "evaluation curve");
  }
  std::string runs_csv =
      "run,configuration,finished,steps,seconds,steps_per_second,final_eval_steps,"
      "final_eval_mean,final_eval_std,final_train_mean\n";
  std::string runs_table =
      "| run | finished | steps | training time (s) | steps/s | final evaluation |\n"
      "|---|---|---|---|---|---|\n";
  for (const RunSummary& r : summary.runs) {
    runs_csv += csv_cell(r.name) + "," + csv_cell(seed_group(r.name, sweep_name(sweep))) + "," +
                (r.finished ? "1" : "0") + "," + std::to_string(r.steps) + "," +
                number(r.seconds, "%.3f") + "," + number(r.steps_per_second, "%.2f") + "," +
                (r.final_eval_mean ? std::to_string(r.final_eval_steps) : "") + "," +
                number(r.final_eval_mean.value_or(kNaN), "%.10g") + "," +
                number(r.final_eval_std.value_or(kNaN), "%.10g") + "," +
                number(r.final_train_mean.value_or(kNaN), "%.10g") + "\n";
    runs_table += "| " + r.name + " | " + (r.finished ? "yes" : "no") + " | " +
                  std::to_string(r.steps) + " | " + number(r.seconds, "%.1f") + " | " +
                  number(r.steps_per_second, "%.0f") + " | " +
                  (r.final_eval_mean ? number(*r.final_eval_mean, "%.2f") + " ± " +
                                           number(r.final_eval_std.value_or(kNaN), "%.2f") +
                                           " at " + std::to_string(r.final_eval_steps) + " steps"
                                     : "–") +
                  " |\n";
  }
  int finished = 0;
  for (const RunSummary& r : summary.runs) finished += r.finished;
  std::string page = "# Sweep " + sweep.output + "\n\n";
  page += "Experiment `" + sweep.experiment_file.string() + "`; " +
          std::to_string(summary.runs.size()) + " runs (" + std::to_string(finished) +
          " finished) in " + std::to_string(summary.configurations.size()) +
          " configurations (runs whose names differ only by their seed token).\n\n";
  page += "- Wall time: " + duration(summary.wall_seconds) + ", from the first start to the " +
          "last end of the " + std::to_string(summary.processes) +
          " process(es) in sweep_log.csv (idle time between invocations included).\n";
  page += "- Busy wall time: " + duration(summary.busy_seconds) +
          ", while at least one process ran (the " + std::to_string(summary.ended_processes) +
          " process(es) that logged their end).\n";
  page += "- Training time summed over runs: " + duration(summary.run_seconds) + ".\n\n";
  page +=
      "## Final evaluation\n\nThe last row of each finished run's eval.csv (its evaluation "
      "at the end of training); mean, population standard deviation, minimum and maximum "
      "over the seeds of each configuration; steps/s averaged over them.\n\n" +
      table + "\n";
  for (const auto& [file, caption] : figures) page += "![" + caption + "](" + file + ")\n\n";
  page +=
      "## Runs\n\nSteps/s: environment steps per second of training, from progress.csv "
      "(over every process that trained the run).\n\n" +
      runs_table;
  write_file_atomically(directory / "configurations.csv", configurations, "sweep summary");
  write_file_atomically(directory / "runs.csv", runs_csv, "sweep summary");
  write_file_atomically(directory / "summary.md", page, "sweep summary");
}

}  // namespace tendril::sweeps
