#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace tendril {

// The one logging path of a run's numbers: named scalars recorded during an iteration, then
// written together by `dump(step)` to
//   progress.csv — one row per dump, columns named as Stable-Baselines3 names them
//                  ("time/total_timesteps", "rollout/ep_rew_mean", ...); a key first seen later
//                  adds a column and the file is rewritten with the wider header, as SB3 does;
//   events.out.tfevents.* — TensorBoard's event file (TFRecord framing, Event/Summary protobufs
//                  with simple_value), which TensorBoard reads.
//
// Every write is checked: a full disk or an I/O error raises Error naming the file. A resumed
// log holds one timeline: rows and events of steps after `resume_step` (logged after the
// checkpoint a run resumes from, by a process that was then killed) are dropped from
// progress.csv and from the earlier event files, as is a record torn by a kill.
class ScalarLog {
 public:
  // Creates (or, when resuming, continues) the files in `directory`.
  explicit ScalarLog(const std::filesystem::path& directory, bool resume = false,
                     int64_t resume_step = std::numeric_limits<int64_t>::max());

  void record(const std::string& key, double value) { pending_[key] = value; }
  void dump(int64_t step);
  // Writes `scalars` at `step` to the event file only (not to progress.csv, whose rows are the
  // training iterations): the evaluations, which TensorBoard shows beside the training curves.
  void write_events(int64_t step, const std::map<std::string, double>& scalars);

  const std::filesystem::path& csv_path() const { return csv_path_; }
  const std::filesystem::path& event_path() const { return event_path_; }

 private:
  void write_event(const std::string& payload);
  void rewrite_csv();

  std::filesystem::path csv_path_, event_path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;  // every row so far, for header widening
  std::map<std::string, double> pending_;
};

// Reads back the scalars of a TensorBoard event file as (tag, step, value) triples, verifying
// every record's checksums; raises tendril::Error on a corrupt file. For tests and tools.
struct EventScalar {
  std::string tag;
  int64_t step;
  float value;
};
std::vector<EventScalar> read_event_scalars(const std::filesystem::path& file);

// Rewrites an event file (atomically) without the records of steps after `last_step` and
// without a trailing record that is torn or corrupt; returns how many records were dropped.
int truncate_event_file(const std::filesystem::path& file, int64_t last_step);

}  // namespace tendril
