// Run records: config.yaml carries its checksum, machine.yaml the machine; damage is refused.
#include "tendril/core/run_record.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/error_message.hpp"

namespace tendril {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / ("tendril_run_record_" + name);
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

constexpr const char* kConfig = "kind: experiment\nseed: 3\nalgo: {gamma: 0.9}\n";

TEST(RunRecord, TheConfigReadsBackExactlyAndTheMachineIsRecorded) {
  const fs::path run = fresh("round_trip");
  write_run_record(run, kConfig);
  EXPECT_EQ(read_run_config_text(run), kConfig);
  EXPECT_EQ(load_run_config(run).get<int>("seed"), 3);
  std::ifstream machine(run / "machine.yaml");
  std::string first;
  std::getline(machine, first);
  EXPECT_FALSE(first.empty());
}

TEST(RunRecord, AnEditedOrDamagedConfigIsRefusedByName) {
  const fs::path run = fresh("edited");
  write_run_record(run, kConfig);
  std::ifstream in(run / "config.yaml", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  text.replace(text.find("seed: 3"), 7, "seed: 4");
  write(run / "config.yaml", text);
  const std::string message = testing::error_message([&] { load_run_config(run); });
  EXPECT_NE(message.find("damaged or edited"), std::string::npos) << message;
  EXPECT_NE(message.find("config.yaml"), std::string::npos) << message;
}

TEST(RunRecord, AConfigWithoutAChecksumLineIsReadAsItIs) {
  const fs::path run = fresh("legacy");
  write(run / "config.yaml", kConfig);
  EXPECT_EQ(read_run_config_text(run), kConfig);
}

TEST(RunRecord, ADirectoryWithoutAConfigIsNotARun) {
  const fs::path run = fresh("empty");
  const std::string message = testing::error_message([&] { read_run_config_text(run); });
  EXPECT_NE(message.find("not a run directory"), std::string::npos) << message;
}

}  // namespace
}  // namespace tendril
