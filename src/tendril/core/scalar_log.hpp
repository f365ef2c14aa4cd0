#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
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
class ScalarLog {
 public:
  // Creates (or appends to, when resuming) the files in `directory`.
  explicit ScalarLog(const std::filesystem::path& directory, bool resume = false);

  void record(const std::string& key, double value) { pending_[key] = value; }
  void dump(int64_t step);

  const std::filesystem::path& csv_path() const { return csv_path_; }
  const std::filesystem::path& event_path() const { return event_path_; }

 private:
  void write_event(const std::string& payload);
  void rewrite_csv();

  std::filesystem::path csv_path_, event_path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;  // every row so far, for header widening
  std::map<std::string, double> pending_;
  std::ofstream events_;
};

// Reads back the scalars of a TensorBoard event file as (tag, step, value) triples, verifying
// every record's checksums; raises tendril::Error on a corrupt file. For tests and tools.
struct EventScalar {
  std::string tag;
  int64_t step;
  float value;
};
std::vector<EventScalar> read_event_scalars(const std::filesystem::path& file);

}  // namespace tendril
