#include "tendril/dashboard/run_state.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

namespace tendril::dashboard {

namespace fs = std::filesystem;

namespace {

constexpr std::streamoff kTailBytes = 64 * 1024;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream stream(line);
  while (std::getline(stream, cell, ',')) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    cells.push_back(cell);
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double number(const std::string& cell) {
  double value = RunState::kUnknown;
  const char* begin = cell.data() + (!cell.empty() && cell.front() == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, cell.data() + cell.size(), value);
  return error == std::errc() && end == cell.data() + cell.size() ? value : RunState::kUnknown;
}

// The newest checkpoint's steps (checkpoints/step_<N>.ckpt), or −1.
int64_t newest_checkpoint(const ServedRoot& root, const fs::path& directory) {
  int64_t newest = -1;
  const std::optional<fs::path> folder = root.contain(directory / "checkpoints");
  if (!folder) return newest;
  std::error_code error;
  for (fs::directory_iterator it(*folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("step_", 0) != 0 || it->path().extension() != ".ckpt") continue;
    int64_t steps = 0;
    const char* first = name.data() + 5;
    const char* last = name.data() + name.size() - 5;  // before ".ckpt"
    const auto [stop, failure] = std::from_chars(first, last, steps);
    if (failure == std::errc() && stop == last) newest = std::max(newest, steps);
  }
  return newest;
}

// The process holding the flock on `directory`/run.lock, or 0.
int64_t lock_holder(const ServedRoot& root, const fs::path& directory, const HeldLocks& locks) {
  const std::optional<fs::path> file = root.served_file(directory / "run.lock");
  struct stat status {};
  if (!file || ::stat(file->c_str(), &status) != 0) return 0;
  const auto found =
      locks.find({(static_cast<uint64_t>(major(status.st_dev)) << 32) | minor(status.st_dev),
                  static_cast<uint64_t>(status.st_ino)});
  return found == locks.end() ? 0 : found->second;
}

}  // namespace

double LastRow::value(const std::string& column) const {
  for (std::size_t c = 0; c < columns.size() && c < values.size(); ++c) {
    if (columns[c] == column) return values[c];
  }
  return RunState::kUnknown;
}

LastRow last_csv_row(const fs::path& file) {
  LastRow row;
  std::ifstream in(file, std::ios::binary);
  std::string header;
  if (!in || !std::getline(in, header) || in.eof()) return row;  // no complete header
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff header_end = static_cast<std::streamoff>(header.size()) + 1;
  const std::streamoff start = std::max(header_end, size - kTailBytes);
  in.seekg(start);
  std::string tail(static_cast<std::size_t>(size - start), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  // The last complete line: the text before the final newline, after the one before it.
  std::size_t end = tail.rfind('\n');
  while (end != std::string::npos) {
    const std::size_t begin = end == 0 ? std::string::npos : tail.rfind('\n', end - 1);
    const std::string line = tail.substr(begin == std::string::npos ? 0 : begin + 1,
                                         end - (begin == std::string::npos ? 0 : begin + 1));
    // A line that starts inside the tail's window may be cut at its front: only trust it when
    // a newline precedes it or the window began right after the header.
    const bool whole = begin != std::string::npos || start == header_end;
    if (whole && !line.empty() && line != "\r") {
      row.columns = split(header);
      for (const std::string& cell : split(line)) row.values.push_back(number(cell));
      if (row.values.size() != row.columns.size()) return LastRow{};
      return row;
    }
    if (begin == std::string::npos) break;
    end = begin;
  }
  return row;
}

HeldLocks held_locks() {
  HeldLocks locks;
  std::ifstream in("/proc/locks");
  std::string line;
  while (std::getline(in, line)) {
    // "1: FLOCK  ADVISORY  WRITE 2150 08:02:1051447 0 EOF"; waiters have "->" after the number.
    std::istringstream fields(line);
    std::string ordinal, type, mode, access, device;
    int64_t pid = 0;
    if (!(fields >> ordinal >> type) || type != "FLOCK") continue;
    if (!(fields >> mode >> access >> pid >> device)) continue;
    unsigned major_number = 0, minor_number = 0;
    unsigned long long inode = 0;
    if (std::sscanf(device.c_str(), "%x:%x:%llu", &major_number, &minor_number, &inode) != 3) {
      continue;
    }
    locks[{(static_cast<uint64_t>(major_number) << 32) | minor_number, inode}] = pid;
  }
  return locks;
}

RunState read_run_state(const ServedRoot& root, const fs::path& directory, const Config* config,
                        const HeldLocks& locks) {
  RunState state;
  const auto has = [&](const char* name) { return root.served_file(directory / name).has_value(); };
  const auto last_row = [&](const char* name) {
    const std::optional<fs::path> file = root.served_file(directory / name);
    return file ? last_csv_row(*file) : LastRow{};
  };
  const LastRow progress = last_row("progress.csv");
  const bool counts_epochs = std::find(progress.columns.begin(), progress.columns.end(),
                                       "time/epochs") != progress.columns.end();
  bool has_algorithm = false;
  try {
    has_algorithm = config != nullptr && !config->get_or<std::string>("algorithm", "").empty();
  } catch (const std::exception&) {  // an algorithm that is not a string: still a training run
    has_algorithm = true;
  }
  if (counts_epochs || has("model.tdm")) {
    state.kind = "fit";
  } else if (has_algorithm) {
    state.kind = "training";
  }

  state.last_return = progress.value("rollout/ep_rew_mean");
  // The budget; a config whose key has another type leaves it unknown.
  const auto budget = [&](const Config& section, const char* key) {
    try {
      return section.get_or<double>(key, RunState::kUnknown);
    } catch (const std::exception&) {
      return RunState::kUnknown;
    }
  };
  if (state.kind == "fit") {
    state.steps = progress.value("time/epochs");
    state.last_loss = progress.value("train/val_loss");
    if (std::isnan(state.last_loss)) state.last_loss = progress.value("train/loss");
    if (config != nullptr) state.total = budget(config->child("training"), "epochs");
  } else {
    state.steps = progress.value("time/total_timesteps");
    if (config != nullptr) state.total = budget(*config, "n_timesteps");
  }
  state.last_eval = last_row("eval.csv").value("mean_return");
  state.checkpoint = newest_checkpoint(root, directory);

  state.pid = lock_holder(root, directory, locks);
  if (state.pid != 0) {
    state.status = "running";
  } else if (state.kind == "training") {
    state.status = has("model.policy") ? "finished" : state.checkpoint >= 0 ? "paused" : "stopped";
  } else if (state.kind == "fit") {
    // A fit ends with its test rollouts (evaluation.csv) or, without a test split, at its last
    // epoch; one stopped early by its patience shows as stopped.
    const bool done = has("evaluation.csv") || state.steps >= state.total;
    state.status = done ? "finished" : "stopped";
  }
  return state;
}

}  // namespace tendril::dashboard
