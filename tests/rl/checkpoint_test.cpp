#include "tendril/rl/checkpoint.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

class CheckpointTest : public testing::ScratchDirectoryTest {
 protected:
  CheckpointTest() : ScratchDirectoryTest("checkpoint_test") {}

  void write_example(const fs::path& file, int64_t counter) {
    CheckpointWriter writer;
    writer.write_int("counter", counter);
    writer.write_double("rate", 2.5e-4);
    writer.write_string("algorithm", "PPO");
    writer.write_doubles("statistics", {1.0, -2.0, 3.5});
    Rng rng(42, 7);
    rng.normal();  // leaves a spare normal in the state
    writer.write_rng("rng", rng.state());
    writer.commit(file);
  }

  std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

TEST_F(CheckpointTest, RoundTripsEveryEntryType) {
  const fs::path file = directory_ / "model.pt";
  write_example(file, 12345678901);
  CheckpointReader reader(file);
  EXPECT_EQ(reader.read_int("counter"), 12345678901);
  EXPECT_DOUBLE_EQ(reader.read_double("rate"), 2.5e-4);
  EXPECT_EQ(reader.read_string("algorithm"), "PPO");
  EXPECT_EQ(reader.read_doubles("statistics"), (std::vector<double>{1.0, -2.0, 3.5}));
  Rng rng(42, 7);
  rng.normal();
  EXPECT_EQ(reader.read_rng("rng"), rng.state());
  EXPECT_THROW(reader.read_int("missing"), Error);
  EXPECT_THROW(reader.read_int("rate"), Error);  // a double, not an integer
}

TEST_F(CheckpointTest, CommitReplacesAtomicallyAndLeavesNoTemporaryFile) {
  const fs::path file = directory_ / "model.pt";
  write_example(file, 1);
  write_example(file, 2);
  EXPECT_EQ(CheckpointReader(file).read_int("counter"), 2);
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory_)) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST_F(CheckpointTest, CommitIntoMissingDirectoryRaisesAndWritesNothing) {
  const fs::path file = directory_ / "no_such_dir" / "model.pt";
  EXPECT_THROW(write_example(file, 1), Error);
  EXPECT_FALSE(fs::exists(file.parent_path()));
}

TEST_F(CheckpointTest, TruncatedCorruptAndMissingFilesRaiseNamingTheFile) {
  const fs::path good = directory_ / "good.pt";
  write_example(good, 3);
  const std::string bytes = read_bytes(good);

  const fs::path truncated = directory_ / "truncated.pt";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const fs::path garbage = directory_ / "garbage.pt";
  std::ofstream(garbage, std::ios::binary) << "this is not a checkpoint";
  const fs::path empty = directory_ / "empty.pt";
  std::ofstream(empty, std::ios::binary).flush();

  for (const fs::path& file : {truncated, garbage, empty, directory_ / "absent.pt"}) {
    try {
      CheckpointReader reader(file);
      reader.read_int("counter");
      ADD_FAILURE() << "no error for " << file;
    } catch (const Error& e) {
      EXPECT_EQ(e.where(), file.string());
    }
  }
  EXPECT_EQ(read_bytes(good), bytes);  // reading never modifies
}

}  // namespace
}  // namespace tendril::rl
