#include "tendril/core/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/log.hpp"

namespace tendril {

namespace {

// The PID the lock file names, "" if it names none (a holder between locking and writing).
std::string holder_of(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return "";
  std::string pid(text, static_cast<std::size_t>(n));
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid;
}

}  // namespace

RunLock::RunLock(const std::filesystem::path& directory) { take(directory, true); }

std::optional<RunLock> RunLock::try_take(const std::filesystem::path& directory) {
  RunLock lock;
  if (!lock.take(directory, false)) return std::nullopt;
  return lock;
}

bool RunLock::take(const std::filesystem::path& directory, bool throw_if_held) {
  file_ = directory / kFileName;
  const std::string where = directory.string();
  fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(std::string("cannot create the run's lock file: ") + std::strerror(errno),
                file_.string());
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    if (error == EWOULDBLOCK && !throw_if_held) {
      ::close(fd_);
      fd_ = -1;
      return false;
    }
    // The holder writes its PID right after locking: give it that moment.
    std::string holder = holder_of(fd_);
    for (int attempt = 0; holder.empty() && attempt < 50; ++attempt) {
      ::usleep(2000);
      holder = holder_of(fd_);
    }
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw Error("the run directory is in use by " +
                      (holder.empty() ? std::string("another process") : "process " + holder) +
                      " (lock " + file_.string() + "); wait for it to end or stop it first",
                  where);
    }
    throw Error(std::string("cannot lock the run directory: ") + std::strerror(error), where);
  }
  // A holder that ends normally empties the file: a PID still there is a stale lock.
  const std::string previous = holder_of(fd_);
  if (!previous.empty()) {
    log::warning("taking over ", directory.string(), ": its lock names process ", previous,
                 ", which ended without releasing it (killed?)");
  }
  const std::string pid = std::to_string(static_cast<long>(::getpid())) + "\n";
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw Error(std::string("cannot write the run's lock file: ") + std::strerror(error),
                file_.string());
  }
  return true;
}

RunLock::RunLock(RunLock&& other) noexcept : file_(std::move(other.file_)), fd_(other.fd_) {
  other.fd_ = -1;
}

RunLock& RunLock::operator=(RunLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    file_ = std::move(other.file_);
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

RunLock::~RunLock() {
  if (fd_ < 0) return;
  if (::ftruncate(fd_, 0) != 0) {
    // The PID stays; the next holder reports a stale lock, which is harmless.
  }
  ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace tendril
