#include "tendril/sweeps/sweep_runner.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <optional>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/run_lock.hpp"

namespace tendril::sweeps {

namespace fs = std::filesystem;

const char* to_string(SweepRunStatus status) {
  switch (status) {
    case SweepRunStatus::started:
      return "started";
    case SweepRunStatus::restarted:
      return "restarted";
    case SweepRunStatus::resumed:
      return "resumed";
    case SweepRunStatus::finished_earlier:
      return "finished earlier, kept";
    case SweepRunStatus::busy:
      return "held by another process, left to it";
  }
  return "?";
}

namespace {

bool finished(const fs::path& directory) { return fs::exists(directory / "model.policy"); }

// What to do with a run no other process holds, decided under its lock.
SweepRunStatus plan(const fs::path& directory) {
  if (finished(directory)) return SweepRunStatus::finished_earlier;
  if (!rl::checkpoints(directory).empty()) return SweepRunStatus::resumed;
  return fs::exists(directory / "config.yaml") ? SweepRunStatus::restarted
                                               : SweepRunStatus::started;
}

}  // namespace

std::vector<SweepRunRecord> train_sweep_runs(
    const Sweep& sweep, const std::vector<int>& indices, rl::TrainOptions options,
    const std::function<void(const SweepRunRecord&, bool done)>& on_run) {
  // Runs interrupted before their first checkpoint start again: nothing of them is lost.
  options.restart_unstarted = true;
  const std::vector<Sweep::Run> runs = sweep.runs();
  std::vector<SweepRunRecord> records;
  for (const int index : indices) {
    require(index >= 0 && index < static_cast<int>(runs.size()),
            "no run " + std::to_string(index) + " in a sweep of " + std::to_string(runs.size()),
            sweep.output);
    SweepRunRecord record;
    record.index = index;
    record.directory = sweep.directory(runs[index]);
    std::error_code error;
    fs::create_directories(record.directory, error);
    require(!error, "cannot create the run directory: " + error.message(),
            record.directory.string());
    {
      // Look under the run's lock; train() and resume() take it again for the whole run. A
      // process that slips in between makes them raise, which is told apart below.
      std::optional<RunLock> lock = RunLock::try_take(record.directory);
      record.status = lock ? plan(record.directory) : SweepRunStatus::busy;
    }
    const bool trains = record.status == SweepRunStatus::started ||
                        record.status == SweepRunStatus::restarted ||
                        record.status == SweepRunStatus::resumed;
    if (on_run) on_run(record, !trains);
    if (!trains) {
      records.push_back(record);
      continue;
    }
    try {
      record.result = record.status == SweepRunStatus::resumed
                          ? rl::resume(record.directory, options)
                          : rl::train(rl::Experiment::from_config(sweep.experiment(runs[index])),
                                      record.directory, options);
    } catch (const Error&) {
      if (RunLock::try_take(record.directory)) throw;  // not a race with another process
      record.status = SweepRunStatus::busy;
    }
    if (on_run) on_run(record, true);
    records.push_back(record);
    if (record.result.interrupted) break;
  }
  return records;
}

bool sweep_finished(const Sweep& sweep) {
  for (const Sweep::Run& run : sweep.runs()) {
    if (!finished(sweep.directory(run))) return false;
  }
  return true;
}

void log_sweep_event(const Sweep& sweep, const std::string& event, const SweepShare& share) {
  const fs::path file = fs::path(sweep.output) / "sweep_log.csv";
  fs::create_directories(sweep.output);
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "unknown");
  const double now =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  char row[512];
  std::snprintf(row, sizeof row, "%s,%.3f,%s,%ld,%d,%d\n", event.c_str(), now, host,
                static_cast<long>(::getpid()), share.rank, share.ranks);
  // The header goes in once; a second process racing here at most repeats it, and readers
  // skip rows that repeat the header.
  if (!fs::exists(file)) append_to_file(file, "event,unix_time,host,pid,rank,ranks\n", "sweep log");
  append_to_file(file, row, "sweep log");
}

bool with_summary_lock(const Sweep& sweep, const std::function<void()>& action) {
  fs::create_directories(sweep.output);
  const fs::path file = fs::path(sweep.output) / "summary.lock";
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(std::string("cannot open: ") + std::strerror(errno), file.string());
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return false;
  }
  try {
    action();
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return true;
}

}  // namespace tendril::sweeps
