#pragma once

#include <filesystem>
#include <optional>

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

  // The lock if no live process holds it (a stale one is taken over as by the constructor),
  // nothing if one does: for callers that pass over a busy run instead of failing.
  static std::optional<RunLock> try_take(const std::filesystem::path& directory);

  static constexpr const char* kFileName = "run.lock";
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  RunLock() = default;
  // Takes the lock; false when a live process holds it and `throw_if_held` is not set.
  bool take(const std::filesystem::path& directory, bool throw_if_held);

  int fd_ = -1;
};

}  // namespace tendril
