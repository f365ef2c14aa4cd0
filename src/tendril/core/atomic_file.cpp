#include "tendril/core/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril {

namespace {

void write_all(int fd, std::string_view bytes, std::string_view what, const std::string& where) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const char* reason = n == 0 ? "no space left on device" : std::strerror(errno);
      throw Error("cannot write " + std::string(what) + ": " + reason, where);
    }
    written += static_cast<std::size_t>(n);
  }
}

void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // durability of the rename is best-effort where directories can't be opened
  ::fsync(fd);
  ::close(fd);
}

// Writes `bytes` to a fresh temporary file beside `file`, flushed to disk; returns its path.
std::filesystem::path write_temporary(const std::filesystem::path& file, std::string_view bytes,
                                      std::string_view what) {
  const std::string where = file.string();
  const std::filesystem::path temporary =
      file.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw Error("cannot create " + std::string(what) + " file: " + std::strerror(errno), where);
  }
  try {
    write_all(fd, bytes, what, where);
    if (::fsync(fd) != 0) {
      throw Error("cannot flush " + std::string(what) + ": " + std::strerror(errno), where);
    }
  } catch (...) {
    ::close(fd);
    std::filesystem::remove(temporary);
    throw;
  }
  ::close(fd);
  return temporary;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes,
                           std::string_view what) {
  const std::string where = file.string();
  const std::filesystem::path temporary = write_temporary(file, bytes, what);
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::filesystem::remove(temporary);
    throw Error("cannot move " + std::string(what) + " into place: " + error.message(), where);
  }
  sync_directory(file.parent_path());
}

void write_new_file_atomically(const std::filesystem::path& file, std::string_view bytes,
                               std::string_view what) {
  const std::string where = file.string();
  if (std::filesystem::exists(file)) {
    throw Error(std::string(what) + " file already exists; not overwriting it", where);
  }
  const std::filesystem::path temporary = write_temporary(file, bytes, what);
  // link() fails if `file` exists, so a file that appeared meanwhile is not replaced either.
  const int linked = ::link(temporary.c_str(), file.c_str());
  const int link_error = errno;
  std::filesystem::remove(temporary);
  if (linked != 0) {
    throw Error(
        link_error == EEXIST
            ? std::string(what) + " file already exists; not overwriting it"
            : "cannot move " + std::string(what) + " into place: " + std::strerror(link_error),
        where);
  }
  sync_directory(file.parent_path());
}

void append_to_file(const std::filesystem::path& file, std::string_view bytes,
                    std::string_view what) {
  const std::string where = file.string();
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw Error("cannot open " + std::string(what) + " for writing: " + std::strerror(errno),
                where);
  }
  struct stat before {};
  const bool sized = ::fstat(fd, &before) == 0;
  try {
    write_all(fd, bytes, what, where);
  } catch (...) {
    // A partial append (the disk filled mid-way) is taken back: the file keeps whole rows and
    // whole records only.
    if (sized && ::ftruncate(fd, before.st_size) != 0) {
      // Nothing more to do: readers drop a torn tail (core/scalar_log) on resume.
    }
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) {
    throw Error("cannot write " + std::string(what) + ": " + std::strerror(errno), where);
  }
}

bool is_atomic_write_leftover(const std::string& name) {
  const std::size_t at = name.rfind(".tmp.");
  if (at == std::string::npos || at == 0 || at + 5 == name.size()) return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(at + 5), name.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace tendril
