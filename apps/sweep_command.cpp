// `tendril sweep`: the runs of a sweep file, in one process or shared among the ranks of an MPI
// launch or the tasks of a Slurm job array, and the summary over seeds (docs/sweeps.md).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/sweeps/sweep.hpp"
#include "tendril/sweeps/sweep_runner.hpp"
#include "tendril/sweeps/sweep_share.hpp"
#include "tendril/sweeps/sweep_slurm.hpp"
#include "tendril/sweeps/sweep_summary.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

// This executable's path. Rebuilt while a long sweep runs, the old file is gone and the link
// reads "<path> (deleted)": the path then names the new build, which is the one to run.
fs::path this_program() {
  std::string path = fs::read_symlink("/proc/self/exe").string();
  constexpr std::string_view kDeleted = " (deleted)";
  if (path.ends_with(kDeleted)) path.resize(path.size() - kDeleted.size());
  return path;
}

// Runs `tendril plot <args>` (a child process: matplotlib lives in Python); true on success.
bool plot(const std::vector<std::string>& args) {
  std::vector<std::string> words = {this_program().string(), "plot"};
  words.insert(words.end(), args.begin(), args.end());
  std::fflush(stdout);
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  return child > 0 && ::waitpid(child, &status, 0) == child && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

// The figure of one metric ("rollout/ep_rew_mean" or "eval") over the runs that have data for
// it, seeds grouped into mean ± std exactly as the summary groups them; false if drawing failed.
bool draw(const sweeps::SweepSummary& summary, const std::string& metric, const fs::path& out,
          const std::string& title) {
  std::vector<std::string> args = {"curves"};
  std::string labels;
  for (const sweeps::ConfigurationSummary& c : summary.configurations) {
    bool any = false;
    for (const int i : c.runs) {
      const sweeps::RunSummary& run = summary.runs[i];
      if ((metric == "eval" ? run.eval : run.train).x.empty()) continue;
      args.push_back(run.directory.string());
      any = true;
    }
    if (!any) continue;
    std::string label = c.name;
    for (char& ch : label) ch = ch == ',' ? ';' : ch;
    labels += (labels.empty() ? "" : ",") + label;
  }
  if (labels.empty()) return true;  // nothing logged yet: no figure
  args.insert(args.end(),
              {"--metric", metric, "--labels", labels, "--title", title, "--out", out.string()});
  return plot(args);
}

// With one grid axis besides the seed, of numbers, and two configurations or more finished: the
// final evaluation (mean ± std over seeds) against that axis, from configurations.csv. Returns
// false if drawing failed, and leaves `out` absent when there is nothing to draw.
bool draw_final(const sweeps::SweepSummary& summary, const fs::path& table, const fs::path& out,
                const std::string& title) {
  const auto& configurations = summary.configurations;
  if (configurations.empty() || configurations.front().settings.size() != 1) return true;
  double low = 0.0, high = 0.0;
  int finished = 0;
  for (const sweeps::ConfigurationSummary& c : configurations) {
    const std::string& text = c.settings.front().second;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != 0) return true;
    low = finished == 0 ? value : std::min(low, value);
    high = finished == 0 ? value : std::max(high, value);
    finished += c.final_eval.count > 0;
  }
  if (finished < 2) return true;
  const std::string key = configurations.front().settings.front().first;
  std::vector<std::string> args = {"csv",      table.string(),
                                   "--x",      key,
                                   "--y",      "final_eval_mean",
                                   "--yerr",   "final_eval_std",
                                   "--kind",   "linepoints",
                                   "--labels", "mean ± std over seeds",
                                   "--title",  title,
                                   "--xlabel", key,
                                   "--ylabel", "final evaluation return",
                                   "--out",    out.string()};
  if (low > 0.0 && high >= 10.0 * low) args.push_back("--logx");
  return plot(args);
}

// Writes the sweep's summary (summary/ in its output): tables, curves and figures.
int aggregate(const sweeps::Sweep& sweep, bool figures) {
  const sweeps::SweepSummary summary = sweeps::summarize_sweep(sweep);
  const fs::path directory = fs::path(sweep.output) / "summary";
  fs::create_directories(directory);
  sweeps::write_sweep_summary(sweep, summary, directory, {});  // the tables the figures draw from
  std::vector<std::pair<std::string, std::string>> drawn;
  bool failed = false;
  if (figures) {
    std::string name = fs::absolute(sweep.output).lexically_normal().string();
    while (name.size() > 1 && name.back() == '/') name.pop_back();
    name = fs::path(name).filename().string();
    const char* kinds[][2] = {{"rollout/ep_rew_mean", "training.png"},
                              {"eval", "evaluation.png"},
                              {"final", "final.png"}};
    for (const auto& [metric, file] : kinds) {
      const std::string what = metric;
      const std::string caption = what == "final" ? "final evaluation return, mean ± std over seeds"
                                  : what == "eval"
                                      ? "evaluation return, mean ± std over seeds"
                                      : "training episode return, mean ± std over seeds";
      const fs::path out = directory / file;
      fs::remove(out);  // a figure of an earlier summary is not left beside this one
      const bool ok = what == "final" ? draw_final(summary, directory / "configurations.csv", out,
                                                   name + ": " + caption)
                                      : draw(summary, what, out, name + ": " + caption);
      if (!ok) {
        std::fprintf(stderr, "warning: the figure %s could not be drawn (tendril plot failed)\n",
                     out.c_str());
        failed = true;
      } else if (fs::exists(out)) {
        drawn.emplace_back(file, caption);
      }
    }
  }
  sweeps::write_sweep_summary(sweep, summary, directory, drawn);
  std::printf("summary: %s (%zu configurations, %zu runs; wall time %.1f s)\n",
              (directory / "summary.md").c_str(), summary.configurations.size(),
              summary.runs.size(), summary.wall_seconds);
  return failed ? 1 : 0;
}

}  // namespace

int sweep_slurm_command(const Arguments& line) {
  const sweeps::Sweep sweep = sweeps::Sweep::load(line.positional.front());
  sweeps::SlurmOptions options;
  options.tendril = this_program();
  options.sweep_file = fs::absolute(line.positional.front()).lexically_normal();
  options.working_directory = fs::current_path();
  options.tasks = static_cast<int>(line.integer("tasks", 0, 1, 1 << 20));
  options.max_running = static_cast<int>(line.integer("max-running", 0, 1, 1 << 20));
  options.cpus_per_task = static_cast<int>(line.integer("cpus-per-task", 0, 1, 4096));
  options.job_name = line.value("job-name", "");
  options.time = line.value("time", options.time);
  options.mem = line.value("mem", "");
  options.partition = line.value("partition", "");
  options.account = line.value("account", "");
  options.stop_before =
      static_cast<int>(line.integer("stop-before", options.stop_before, 0, 1 << 24));
  const std::string script = sweeps::slurm_script(sweep, options);
  const fs::path folder = fs::path(sweep.output) / "slurm";
  fs::create_directories(folder);  // the tasks' logs go here too
  const fs::path file = line.value("output", (folder / "sweep.sbatch").string());
  write_file_atomically(file, script, "Slurm script");
  fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  std::printf("%s\nsubmit with:  sbatch %s\n", file.c_str(), file.c_str());
  return 0;
}

int sweep_summarize_command(const Arguments& line) {
  return aggregate(sweeps::Sweep::load(line.positional.front()), !line.has("no-figures"));
}

namespace {

// The runs this process takes: all, its rank's share (--rank/--ranks, or MPI's or Slurm's
// environment), or the one --only names.
std::vector<int> runs_of_this_process(const Arguments& line, int count, sweeps::SweepShare& share) {
  share = sweeps::SweepShare::from_environment();
  require(line.has("rank") == line.has("ranks"), "are given together", "--rank/--ranks");
  if (line.has("ranks")) {
    share.ranks = static_cast<int>(line.integer("ranks", 1, 1, 1 << 20));
    share.rank = static_cast<int>(line.integer("rank", 0, 0, share.ranks - 1));
    share.source = "--rank/--ranks";
  }
  std::vector<int> indices = share.runs(count);
  if (line.has("only")) {
    require(share.ranks == 1, "cannot be combined with several ranks", "--only");
    indices = {static_cast<int>(line.integer("only", 0, 0, count - 1))};
  }
  return indices;
}

}  // namespace

int sweep_list_command(const Arguments& line) {
  const sweeps::Sweep sweep = sweeps::Sweep::load(line.positional.front());
  const std::vector<sweeps::Sweep::Run> runs = sweep.runs();
  sweeps::SweepShare share;
  for (const int i : runs_of_this_process(line, static_cast<int>(runs.size()), share)) {
    std::printf("%3d  %s\n", i, sweep.directory(runs[i]).c_str());
  }
  return 0;
}

int sweep_run_command(const Arguments& line) {
  const sweeps::Sweep sweep = sweeps::Sweep::load(line.positional.front());
  const std::vector<sweeps::Sweep::Run> runs = sweep.runs();
  const int count = static_cast<int>(runs.size());

  sweeps::SweepShare share;
  const std::vector<int> indices = runs_of_this_process(line, count, share);
  const std::string who = share.ranks > 1 ? "[rank " + std::to_string(share.rank) + "/" +
                                                std::to_string(share.ranks) + "] "
                                          : "";
  rl::TrainOptions options;
  options.quiet = line.has("quiet");
  catch_interrupts();
  const auto start = std::chrono::steady_clock::now();
  sweeps::log_sweep_event(sweep, "start", share);
  const auto report = [&](const sweeps::SweepRunRecord& record, bool done) {
    if (!done) {
      std::printf("%s[%d/%d] %s: %s\n", who.c_str(), record.index + 1, count,
                  record.directory.c_str(), sweeps::to_string(record.status));
    } else if (record.status == sweeps::SweepRunStatus::busy ||
               record.status == sweeps::SweepRunStatus::finished_earlier) {
      std::printf("%s[%d/%d] %s: %s\n", who.c_str(), record.index + 1, count,
                  record.directory.c_str(), sweeps::to_string(record.status));
    } else if (!record.result.interrupted) {
      std::printf("%s  %lld steps in %.1f s (%.0f steps/s), final evaluation %.2f +/- %.2f\n",
                  who.c_str(), static_cast<long long>(record.result.timesteps),
                  record.result.seconds, record.result.steps_per_second,
                  record.result.final_eval_mean, record.result.final_eval_std);
    }
    std::fflush(stdout);
  };
  const std::vector<sweeps::SweepRunRecord> records =
      sweeps::train_sweep_runs(sweep, indices, options, report);
  sweeps::log_sweep_event(sweep, "end", share);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!records.empty() && records.back().result.interrupted) {
    const auto& last = records.back();
    std::printf(
        "%s  interrupted by %s after %lld steps; its checkpoint holds the run\n"
        "continue with:  tendril sweep run %s\n",
        who.c_str(), signal_name(last.result.interrupted),
        static_cast<long long>(last.result.timesteps), line.positional.front().c_str());
    return 128 + last.result.interrupted;
  }
  std::printf("%s%zu runs of this process in %.1f s wall time\n", who.c_str(), indices.size(),
              seconds);
  if (!sweeps::sweep_finished(sweep)) {
    std::printf(
        "%sother runs are not finished yet: the process that finishes the last one writes the "
        "summary (or: tendril sweep summarize %s)\n",
        who.c_str(), line.positional.front().c_str());
    return 0;
  }
  int status = 0;
  const bool wrote =
      sweeps::with_summary_lock(sweep, [&] { status = aggregate(sweep, !line.has("no-figures")); });
  if (!wrote) std::printf("%sanother process is writing the summary\n", who.c_str());
  return status;
}

}  // namespace tendril::apps
