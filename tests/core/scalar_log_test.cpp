#include "tendril/core/scalar_log.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / ("tendril_" + name);
  fs::remove_all(directory);
  return directory;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(Crc32c, KnownCheckValue) {
  // The CRC-32C check value of the ASCII digits "123456789".
  EXPECT_EQ(crc32c("123456789", 9), 0xE3069283u);
  EXPECT_EQ(crc32c("", 0), 0u);
}

TEST(ScalarLog, WritesCsvWithWideningHeaderAndEvents) {
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

TEST(ScalarLog, ResumeAppendsToTheExistingCsv) {
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

TEST(ScalarLog, CorruptEventFileIsRejected) {
  const fs::path directory = fresh_directory("scalar_log_corrupt");
  fs::path events;
  {
    ScalarLog log(directory);
    log.record("x", 1);
    log.dump(1);
    events = log.event_path();
  }
  std::string bytes = read_text(events);
  bytes[bytes.size() - 6] ^= 0x40;  // flip a bit inside the last record's payload
  std::ofstream(events, std::ios::binary) << bytes;
  EXPECT_THROW(read_event_scalars(events), Error);
  std::ofstream(events, std::ios::binary) << bytes.substr(0, bytes.size() - 3);
  EXPECT_THROW(read_event_scalars(events), Error);
}

}  // namespace
}  // namespace tendril
