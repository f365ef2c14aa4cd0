// `tendril report`: the numbers of runs outside a sweep — training means at given steps,
// final evaluations, training time — per run and as mean ± std over seeds.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/sweeps/runs_report.hpp"
#include "tendril/sweeps/sweep_summary.hpp"

namespace tendril::apps {

namespace {

// The steps of `--at 500000,1000000`: positive whole numbers separated by commas.
std::vector<double> steps_of(const std::string& text) {
  std::vector<double> steps;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string word = text.substr(start, comma - start);
    require(!word.empty() && word.find_first_not_of("0123456789") == std::string::npos &&
                word.size() <= 15 && std::stod(word) > 0.0,
            "expects positive whole numbers of steps separated by commas, got '" + text + "'",
            "--at");
    steps.push_back(std::stod(word));
    start = comma + 1;
  }
  return steps;
}

}  // namespace

int report_command(const Arguments& line) {
  require(!line.positional.empty(), "expects run directories or directories of runs",
          "command line");
  require(line.overrides.empty(), "takes no --set", "command line");
  const std::vector<double> steps =
      line.has("at") ? steps_of(line.value("at", "")) : std::vector<double>{};
  std::vector<std::filesystem::path> paths(line.positional.begin(), line.positional.end());
  const sweeps::SweepSummary summary = sweeps::summarize_runs(sweeps::run_directories(paths));
  std::fputs(sweeps::runs_report(summary, steps).c_str(), stdout);
  return 0;
}

}  // namespace tendril::apps
