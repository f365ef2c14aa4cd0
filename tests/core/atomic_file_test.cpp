#include "tendril/core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril {
namespace {

class AtomicFile : public testing::ScratchDirectoryTest {
 protected:
  AtomicFile() : ScratchDirectoryTest("atomic_file") {}
  std::string read(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

TEST_F(AtomicFile, ANewFileIsWrittenWholeAndNothingIsLeftBeside) {
  const auto file = directory_ / "data.csv";
  write_new_file_atomically(file, "a,b\n1,2\n", "data set");
  EXPECT_EQ(read(file), "a,b\n1,2\n");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(directory_)) {
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

TEST_F(AtomicFile, AnExistingFileIsNeverReplaced) {
  const auto file = directory_ / "data.csv";
  write_new_file_atomically(file, "first\n", "data set");
  const std::string message =
      testing::error_message([&] { write_new_file_atomically(file, "second\n", "data set"); });
  EXPECT_NE(message.find("data.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("already exists"), std::string::npos) << message;
  EXPECT_EQ(read(file), "first\n");
  // write_file_atomically, by contrast, replaces.
  write_file_atomically(file, "third\n", "data set");
  EXPECT_EQ(read(file), "third\n");
}

TEST_F(AtomicFile, AMissingDirectoryIsAnErrorNamingTheFile) {
  const auto file = directory_ / "missing" / "data.csv";
  EXPECT_NE(testing::error_message([&] {
              write_new_file_atomically(file, "x", "data set");
            }).find("missing/data.csv"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril
