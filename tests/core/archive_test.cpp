#include "tendril/core/archive.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/crc32c.hpp"

namespace tendril {
namespace {

ArchiveWriter sample() {
  ArchiveWriter writer("checkpoint");
  writer.put("format", int64_t{3});
  writer.put("gamma", 0.99);
  writer.put("algorithm", "PPO");
  writer.put_floats("weights", Eigen::VectorXf::LinSpaced(7, -1.0f, 2.0f));
  writer.put_doubles("returns", std::vector<double>{1.5, -2.25});
  const Snapshot blob{std::byte{1}, std::byte{0}, std::byte{255}};
  writer.put_bytes("envs", blob);
  Rng rng(5, 2);
  rng.normal();
  writer.put_rng("rng", rng);
  return writer;
}

TEST(Archive, RoundTripsEveryKindOfEntry) {
  const ArchiveReader reader =
      ArchiveReader::from_bytes(sample().serialize(), "checkpoint", "test.ckpt");
  EXPECT_EQ(reader.get_int("format"), 3);
  EXPECT_EQ(reader.get_double("gamma"), 0.99);
  EXPECT_EQ(reader.get_string("algorithm"), "PPO");
  EXPECT_EQ(reader.get_floats("weights", 7), Eigen::VectorXf::LinSpaced(7, -1.0f, 2.0f));
  EXPECT_EQ(reader.get_doubles("returns"), (std::vector<double>{1.5, -2.25}));
  EXPECT_EQ(reader.get_bytes("envs"), (Snapshot{std::byte{1}, std::byte{0}, std::byte{255}}));
  Rng expected(5, 2);
  expected.normal();
  EXPECT_EQ(reader.get_rng("rng").state(), expected.state());
  EXPECT_TRUE(reader.contains("gamma"));
  EXPECT_FALSE(reader.contains("lambda"));
  EXPECT_NO_THROW(reader.expect_int("format", 3));
}

// Found by tests/fuzz/archive_fuzz under UndefinedBehaviorSanitizer: an empty array entry has no
// storage, and copying zero bytes into its null pointer is undefined behaviour.
TEST(Archive, EmptyArraysRoundTrip) {
  ArchiveWriter writer("checkpoint");
  writer.put_floats("floats", Eigen::VectorXf());
  writer.put_doubles("doubles", std::vector<double>{});
  writer.put_bytes("bytes", Snapshot{});
  const ArchiveReader reader = ArchiveReader::from_bytes(writer.serialize(), "checkpoint", "e");
  EXPECT_EQ(reader.get_floats("floats").size(), 0);
  EXPECT_EQ(reader.get_floats("floats", 0).size(), 0);
  EXPECT_TRUE(reader.get_doubles("doubles").empty());
  EXPECT_TRUE(reader.get_bytes("bytes").empty());
}

TEST(Archive, EveryFlippedBitAndEveryTruncationIsRefused) {
  const std::string bytes = sample().serialize();
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string damaged = bytes;
      damaged[i] = static_cast<char>(damaged[i] ^ (1 << bit));
      EXPECT_NE(
          testing::error_message([&] { ArchiveReader::from_bytes(damaged, "checkpoint", "f"); }),
          "no error")
          << "byte " << i << " bit " << bit;
    }
  }
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    EXPECT_NE(testing::error_message(
                  [&] { ArchiveReader::from_bytes(bytes.substr(0, length), "checkpoint", "f"); }),
              "no error")
        << "cut at " << length;
  }
}

TEST(Archive, ErrorsNameTheFileAndTheEntry) {
  const std::string bytes = sample().serialize();
  const auto reader = ArchiveReader::from_bytes(bytes, "checkpoint", "run/step_8.ckpt");
  EXPECT_EQ(testing::error_message([&] { reader.get_int("lambda"); }),
            "run/step_8.ckpt: missing entry 'lambda'");
  EXPECT_EQ(testing::error_message([&] { reader.get_int("algorithm"); }),
            "run/step_8.ckpt: entry 'algorithm' is not an integer");
  EXPECT_EQ(testing::error_message([&] { reader.get_floats("weights", 8); }),
            "run/step_8.ckpt: entry 'weights' holds 7 values, expected 8");
  EXPECT_EQ(testing::error_message([&] { reader.expect_int("format", 4); }),
            "run/step_8.ckpt: format is 3 in the file, 4 here");
  EXPECT_EQ(testing::error_message([&] { ArchiveReader::from_bytes(bytes, "policy", "m"); }),
            "m: a checkpoint file, not a policy file");
  EXPECT_EQ(
      testing::error_message([&] { ArchiveReader::from_bytes("PK\x03\x04 zip", "policy", "m"); }),
      "m: not a tendril policy file (no archive header)");
  std::string damaged = bytes;
  damaged[20] ^= 1;
  EXPECT_EQ(testing::error_message([&] { ArchiveReader::from_bytes(damaged, "checkpoint", "c"); }),
            "c: corrupt checkpoint file: checksum mismatch (the file was damaged or cut short)");
  // A valid checksum over a newer format version.
  std::string newer = bytes.substr(0, bytes.size() - 4);
  const uint32_t version = 2;
  std::memcpy(newer.data() + 8, &version, sizeof version);
  const uint32_t crc = crc32c(newer.data(), newer.size());
  newer.append(reinterpret_cast<const char*>(&crc), sizeof crc);
  EXPECT_EQ(testing::error_message([&] { ArchiveReader::from_bytes(newer, "checkpoint", "c"); }),
            "c: archive format 2 is not supported (this build reads 1)");
}

class ArchiveFile : public testing::ScratchDirectoryTest {
 protected:
  ArchiveFile() : ScratchDirectoryTest("archive") {}
  const std::filesystem::path& directory() const { return directory_; }
};

TEST_F(ArchiveFile, CommitsAtomicallyAndReadsBack) {
  const auto file = directory() / "model.policy";
  sample().commit(file);
  EXPECT_EQ(ArchiveReader(file, "checkpoint").get_string("algorithm"), "PPO");
  EXPECT_EQ(testing::error_message([&] { ArchiveReader(directory() / "none", "checkpoint"); }),
            (directory() / "none").string() + ": no such file");
  EXPECT_EQ(testing::error_message([&] { ArchiveReader(directory(), "checkpoint"); }),
            directory().string() + ": not a regular file");
  const auto size = std::filesystem::file_size(file);
  EXPECT_EQ(testing::error_message([&] { ArchiveReader(file, "checkpoint", 10); }),
            file.string() + ": is " + std::to_string(size) +
                " bytes, more than the 10 a checkpoint may have");
}

}  // namespace
}  // namespace tendril
