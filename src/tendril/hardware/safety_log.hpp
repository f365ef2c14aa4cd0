#pragma once

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace tendril::hardware {

// Every safety action a bridge takes, with its cause: clamped or refused commands, rate
// limiting, safe commands, emergency stops, lost or stale readings, reconnects, and what the
// robot itself reported (its watchdog, refusals, bad frames). Optionally appended to a CSV file
// as it happens (time_s,action,cause), so a crash loses nothing already logged.
struct SafetyEvent {
  double time_s = 0.0;  // since the log was made
  std::string action;
  std::string cause;
};

class SafetyLog {
 public:
  SafetyLog();
  ~SafetyLog();
  SafetyLog(const SafetyLog&) = delete;
  SafetyLog& operator=(const SafetyLog&) = delete;

  // Appends to `file` from now on (Error naming it if it cannot be opened).
  void write_to(const std::filesystem::path& file);
  void record(const std::string& action, const std::string& cause);
  const std::vector<SafetyEvent>& events() const { return events_; }
  int count(const std::string& action) const;

 private:
  std::vector<SafetyEvent> events_;
  std::chrono::steady_clock::time_point start_;
  std::FILE* file_ = nullptr;
};

}  // namespace tendril::hardware
