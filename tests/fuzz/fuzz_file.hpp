#pragma once

// The readers under test take file paths: the fuzz input goes to a file of this process's own.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace tendril::fuzzing {

// A directory under the temporary folder for this process, created on first use.
inline const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path directory = [] {
    const auto path =
        std::filesystem::temp_directory_path() / ("tendril_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return directory;
}

// Writes `bytes` to `name` in the scratch directory and returns its path.
inline std::filesystem::path write_file(const std::string& name, const void* bytes, size_t size) {
  const std::filesystem::path file = scratch_directory() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace tendril::fuzzing
