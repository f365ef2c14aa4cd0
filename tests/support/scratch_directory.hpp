#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace tendril::testing {

// A fixture owning an empty directory under the system's temporary folder for the duration of
// one test (named after `prefix` and the process, so parallel test programs never share it).
class ScratchDirectoryTest : public ::testing::Test {
 protected:
  explicit ScratchDirectoryTest(const std::string& prefix)
      : directory_(std::filesystem::temp_directory_path() /
                   ("tendril_" + prefix + "_" + std::to_string(::getpid()))) {}
  void SetUp() override { std::filesystem::create_directories(directory_); }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path directory_;
};

}  // namespace tendril::testing
