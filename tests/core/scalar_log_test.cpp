#include "tendril/core/scalar_log.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril {
namespace {

namespace fs = std::filesystem;

using testing::error_message;

// TFRecord's checksum of a record length: the CRC-32C rotated right by 15 bits plus 0xa282ead8.
uint32_t masked_crc(const void* data, std::size_t size) {
  const uint32_t crc = crc32c(data, size);
  return ((crc >> 15) | (crc << 17)) + 0xA282EAD8u;
}

// A scratch directory of the test's own (unique to the process, removed afterwards).
class ScalarLogFiles : public testing::ScratchDirectoryTest {
 protected:
  ScalarLogFiles() : ScratchDirectoryTest("scalar_log") {}
  fs::path fresh_directory(const std::string& name) const { return directory_ / name; }
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(Crc32c, KnownCheckValue) {
  // The CRC-32C check value of the ASCII digits "123456789".
  EXPECT_EQ(crc32c("123456789", 9), 0xE3069283u);
  EXPECT_EQ(crc32c("", 0), 0u);
}

TEST_F(ScalarLogFiles, WritesCsvWithWideningHeaderAndEvents) {
  const fs::path directory = fresh_directory("scalar_log");
  fs::path events;
  {
    ScalarLog log(directory);
    log.record("time/total_timesteps", 2048);
    log.record("rollout/ep_rew_mean", -1200.5);
    log.dump(2048);
    log.record("time/total_timesteps", 4096);
    log.record("rollout/ep_rew_mean", -900.25);
    log.record("train/approx_kl", 0.0125);
    log.dump(4096);
    events = log.event_path();
  }
  EXPECT_EQ(read_text(directory / "progress.csv"),
            "rollout/ep_rew_mean,time/total_timesteps,train/approx_kl\n"
            "-1200.5,2048,\n"
            "-900.25,4096,0.0125\n");
  const std::vector<EventScalar> scalars = read_event_scalars(events);
  ASSERT_EQ(scalars.size(), 5u);
  EXPECT_EQ(scalars[0].tag, "rollout/ep_rew_mean");
  EXPECT_EQ(scalars[0].step, 2048);
  EXPECT_FLOAT_EQ(scalars[0].value, -1200.5f);
  EXPECT_EQ(scalars[4].tag, "train/approx_kl");
  EXPECT_EQ(scalars[4].step, 4096);
  EXPECT_FLOAT_EQ(scalars[4].value, 0.0125f);
}

TEST_F(ScalarLogFiles, ResumeAppendsToTheExistingCsv) {
  const fs::path directory = fresh_directory("scalar_log_resume");
  {
    ScalarLog log(directory);
    log.record("a", 1);
    log.dump(1);
  }
  {
    ScalarLog log(directory, /*resume=*/true);
    log.record("a", 2);
    log.record("b", 3);
    log.dump(2);
  }
  EXPECT_EQ(read_text(directory / "progress.csv"), "a,b\n1,\n2,3\n");
}

TEST_F(ScalarLogFiles, CorruptEventFileIsRejected) {
  const fs::path directory = fresh_directory("scalar_log_corrupt");
  fs::path events;
  {
    ScalarLog log(directory);
    log.record("x", 1);
    log.dump(1);
    events = log.event_path();
  }
  const std::string bytes = read_text(events);
  // A flipped bit inside the last record's payload fails its CRC.
  std::string flipped = bytes;
  flipped[flipped.size() - 6] ^= 0x40;
  std::ofstream(events, std::ios::binary) << flipped;
  EXPECT_NE(error_message([&] { read_event_scalars(events); }).find("corrupt record"),
            std::string::npos);
  // The intact file cut short inside its last record, and inside a record header.
  std::ofstream(events, std::ios::binary) << bytes.substr(0, bytes.size() - 3);
  EXPECT_NE(error_message([&] { read_event_scalars(events); }).find("truncated record"),
            std::string::npos);
  std::ofstream(events, std::ios::binary) << bytes + bytes.substr(0, 7);
  EXPECT_NE(error_message([&] { read_event_scalars(events); }).find("truncated record header"),
            std::string::npos);
  // A record length beyond the file (with a valid length CRC) is a truncation, not a wrap-around.
  std::string huge = bytes;
  const uint64_t length = ~uint64_t{0} - 8;
  std::memcpy(huge.data(), &length, 8);
  const uint32_t length_crc = masked_crc(&length, 8);
  std::memcpy(huge.data() + 8, &length_crc, 4);
  std::ofstream(events, std::ios::binary) << huge;
  EXPECT_NE(error_message([&] { read_event_scalars(events); }).find("truncated record"),
            std::string::npos);
  std::ofstream(events, std::ios::binary) << bytes;
  EXPECT_EQ(read_event_scalars(events).size(), 1u);
}

}  // namespace
}  // namespace tendril
