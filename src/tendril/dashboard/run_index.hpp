#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/dashboard/run_state.hpp"
#include "tendril/dashboard/served_root.hpp"

namespace tendril::dashboard {

// A run directory as the dashboard lists it (paths relative to the served root, '/'-separated).
struct RunEntry {
  std::string path;
  std::string name;       // the directory's name
  std::string env_id;     // from config.yaml, when it says
  std::string algorithm;  // from config.yaml, when it says
  bool has_progress = false;
  bool has_eval = false;
  int episodes = 0;       // files in episodes/
  double modified = 0.0;  // newest of config, progress and eval, seconds since the epoch
  std::string problem;    // e.g. an unreadable config.yaml
  RunState state;         // status, steps, last return
};

// A directory holding runs side by side (a sweep's output, seeds of one experiment).
struct SweepEntry {
  std::string path;
  std::string name;
  std::vector<std::string> runs;  // paths of the runs directly inside it
  // `tendril sweep`'s summary/summary.md and its figures (.png, .svg), when written.
  std::string summary;
  std::vector<std::string> figures;
};

struct RunIndex {
  std::vector<RunEntry> runs;
  std::vector<SweepEntry> sweeps;
};

// Whether `directory` (inside the root) is a run: it holds config.yaml, progress.csv or eval.csv
// inside the root (a symbolic link leading out of it does not count).
bool is_run_directory(const ServedRoot& root, const std::filesystem::path& directory);

// The runs at most `max_depth` directories below the root (not looking inside runs or hidden
// directories), sorted by path; a directory below the root with at least two runs directly
// inside, or with one and a sweep summary (summary/summary.md), is a sweep. The root itself is
// never listed as a sweep: its runs are the list.
RunIndex index_runs(const ServedRoot& root, int max_depth = 6);

// The episode files (*.tep) of a run directory's episodes/, sorted by name: only those that are
// regular files inside the root, in an episodes/ inside the root (links are followed only as far
// as the root reaches).
std::vector<std::filesystem::path> episode_files(const ServedRoot& root,
                                                 const std::filesystem::path& run_directory);

}  // namespace tendril::dashboard
