#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::envs {

// Every transition of a run as one CSV row — the data behind trajectory figures (the UR5 flange
// paths, the beam's tip paths, a limb's bend angles). Columns: episode, step, time (s, the
// scene's clock), reward, terminated, truncated, observation_i (before the step), action_i
// (environment units), next_observation_i, then the step's info values and the scene's named
// values by name (empty where a step lacks one). Numbers are written exactly (%.17g).
// The file must not exist; every write is checked (a full disk is an Error naming the file).
class TraceWriter : public RunObserver {
 public:
  explicit TraceWriter(const std::filesystem::path& file);
  // Flushes and checks the file; raises Error naming it when a write failed.
  void close();

  void on_step(const StepView& step) override;

 private:
  void write_header(const StepView& step, const std::vector<std::pair<std::string, double>>& scene);

  std::filesystem::path file_;
  std::ofstream out_;
  std::vector<std::string> columns_;
  bool header_written_ = false;
};

}  // namespace tendril::envs
