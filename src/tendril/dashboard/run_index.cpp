#include "tendril/dashboard/run_index.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/error.hpp"

namespace tendril::dashboard {

namespace fs = std::filesystem;

namespace {

double modified_seconds(const ServedRoot& root, const fs::path& path) {
  const std::optional<fs::path> file = root.served_file(path);
  if (!file) return 0.0;
  std::error_code error;
  const auto time = fs::last_write_time(*file, error);
  if (error) return 0.0;
  const auto system = std::chrono::file_clock::to_sys(time);
  return std::chrono::duration<double>(system.time_since_epoch()).count();
}

RunEntry describe_run(const ServedRoot& root, const fs::path& directory, const HeldLocks& locks) {
  RunEntry run;
  run.path = root.relative(directory);
  run.name = directory.filename().string();
  run.has_progress = root.served_file(directory / "progress.csv").has_value();
  run.has_eval = root.served_file(directory / "eval.csv").has_value();
  run.episodes = static_cast<int>(episode_files(root, directory).size());
  for (const char* file : {"config.yaml", "progress.csv", "eval.csv"}) {
    run.modified = std::max(run.modified, modified_seconds(root, directory / file));
  }
  std::optional<Config> config;
  if (const std::optional<fs::path> config_file = root.served_file(directory / "config.yaml")) {
    try {
      config = Config::load_file(*config_file);
      run.env_id = config->child("env").get_or<std::string>("id", "");
      run.algorithm = config->get_or<std::string>("algorithm", "");
    } catch (const std::exception& e) {
      run.problem = std::string("config.yaml: ") + e.what();
    }
  }
  run.state = read_run_state(root, directory, config ? &*config : nullptr, locks);
  return run;
}

// A sweep's summary/summary.md and figures, when `tendril sweep` wrote them.
void find_summary(const ServedRoot& root, const fs::path& directory, SweepEntry& sweep) {
  const std::optional<fs::path> page = root.served_file(directory / "summary" / "summary.md");
  if (!page) return;
  sweep.summary = root.relative(*page);
  std::error_code error;
  for (fs::directory_iterator it(page->parent_path(), error), end; !error && it != end;
       it.increment(error)) {
    const std::string extension = it->path().extension().string();
    if ((extension == ".png" || extension == ".svg") && root.served_file(it->path())) {
      sweep.figures.push_back(root.relative(it->path()));
    }
  }
  std::sort(sweep.figures.begin(), sweep.figures.end());
}

bool skipped(const fs::path& directory) {
  const std::string name = directory.filename().string();
  return name.empty() || name.front() == '.' || name == "checkpoints" || name == "episodes" ||
         name == "node_modules";
}

// Adds the runs in `directory` (depth levels below the root) and returns how many of them lie
// directly inside it.
int visit(const ServedRoot& root, const fs::path& directory, int depth, int max_depth,
          const HeldLocks& locks, RunIndex& index) {
  if (is_run_directory(root, directory)) {
    index.runs.push_back(describe_run(root, directory, locks));
    return 1;
  }
  if (depth >= max_depth) return 0;
  std::vector<fs::path> children;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    // Symbolic links are not followed: everything listed lies inside the root. (A link that
    // cannot be resolved, such as a loop, is no directory.)
    std::error_code entry_error;
    if (it->is_symlink(entry_error) || !it->is_directory(entry_error) || entry_error) continue;
    if (!skipped(it->path())) {
      children.push_back(it->path());
    }
  }
  std::sort(children.begin(), children.end());
  SweepEntry sweep{root.relative(directory), directory.filename().string(), {}, {}, {}};
  for (const fs::path& child : children) {
    const std::size_t before = index.runs.size();
    if (visit(root, child, depth + 1, max_depth, locks, index) == 1) {
      sweep.runs.push_back(index.runs[before].path);
    }
  }
  if (depth == 0 || sweep.runs.empty()) return 0;  // the root's runs are the whole list
  find_summary(root, directory, sweep);
  if (sweep.runs.size() >= 2 || !sweep.summary.empty()) index.sweeps.push_back(std::move(sweep));
  return 0;
}

}  // namespace

bool is_run_directory(const ServedRoot& root, const fs::path& directory) {
  for (const char* name : {"config.yaml", "progress.csv", "eval.csv"}) {
    if (root.served_file(directory / name)) return true;
  }
  return false;
}

RunIndex index_runs(const ServedRoot& root, int max_depth) {
  RunIndex index;
  visit(root, root.path(), 0, max_depth, held_locks(), index);
  std::sort(index.runs.begin(), index.runs.end(),
            [](const RunEntry& a, const RunEntry& b) { return a.path < b.path; });
  std::sort(index.sweeps.begin(), index.sweeps.end(),
            [](const SweepEntry& a, const SweepEntry& b) { return a.path < b.path; });
  return index;
}

std::vector<fs::path> episode_files(const ServedRoot& root, const fs::path& run_directory) {
  std::vector<fs::path> files;
  std::error_code error;
  const std::optional<fs::path> folder = root.contain(run_directory / "episodes");
  if (!folder || !fs::is_directory(*folder, error)) return files;
  for (fs::directory_iterator it(*folder, error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".tep" && root.served_file(it->path())) {
      files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace tendril::dashboard
