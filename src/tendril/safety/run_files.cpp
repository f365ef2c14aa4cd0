#include "tendril/safety/run_files.hpp"

#include <utility>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"

namespace tendril::safety {

void start_run_directory(const std::filesystem::path& run_directory, const Config& experiment) {
  namespace fs = std::filesystem;
  if (fs::exists(run_directory) && !fs::is_empty(run_directory)) {
    throw Error("the run directory is not empty; nothing is overwritten", run_directory.string());
  }
  fs::create_directories(run_directory);
  write_new_file_atomically(run_directory / "config.yaml", experiment.dump() + "\n", "config");
}

RunScalarLog::RunScalarLog(const std::filesystem::path& run_directory,
                           std::function<void(rl::TrainStats&)> extra)
    : log_(run_directory, /*resuming=*/false, 0), extra_(std::move(extra)) {}

bool RunScalarLog::on_iteration(const rl::Progress& progress) {
  rl::Progress extended = progress;
  if (extra_) extra_(extended.train);
  return log_.on_iteration(extended);
}

}  // namespace tendril::safety
