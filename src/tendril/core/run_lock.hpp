#pragma once

#include <filesystem>

namespace tendril {

// An exclusive lock on a run directory while one process writes it: an advisory flock(2) on
// `<directory>/run.lock`, which holds the PID of the process that took it. The kernel drops the
// lock when its holder exits, however it exits, so a lock left by a killed process is stale and
// taken over (with a warning naming the process that left it); a live holder makes the
// constructor raise Error naming its PID. Movable, not copyable; released on destruction (the
// file stays, emptied).
class RunLock {
 public:
  explicit RunLock(const std::filesystem::path& directory);
  RunLock(RunLock&& other) noexcept;
  RunLock& operator=(RunLock&& other) noexcept;
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();

  static constexpr const char* kFileName = "run.lock";
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace tendril
