#include "tendril/core/file_kind.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"

namespace tendril {
namespace {

using testing::error_message;

TEST(FileKind, AFileOfTheExpectedKindReads) {
  const Config file = Config::parse("kind: sweep\nexperiment: e.yaml\n", "s.yaml");
  expect_kind(file, file_kind::kSweep);
  EXPECT_EQ(file.get<std::string>("kind"), "sweep");
}

// Files written before the key read on, and the resolved config.yaml of a run names its kind.
TEST(FileKind, AFileWithoutAKindIsTakenAsTheExpectedOneAndRecordsIt) {
  const Config file = Config::parse("algorithm: ppo\n", "e.yaml");
  expect_kind(file, file_kind::kExperiment);
  EXPECT_NE(file.dump_resolved().find("kind: experiment"), std::string::npos)
      << file.dump_resolved();
  EXPECT_EQ(file.dump().find("kind"), std::string::npos);  // the file as given is not changed
}

TEST(FileKind, AFileOfAnotherKindNamesWhatReadsIt) {
  const Config file = Config::parse("kind: sweep\n", "s.yaml");
  const std::string message = error_message([&] { expect_kind(file, file_kind::kExperiment); });
  EXPECT_NE(message.find("s.yaml: kind"), std::string::npos) << message;
  EXPECT_NE(message.find("says `kind: sweep`, a file for tendril sweep run"), std::string::npos)
      << message;
  EXPECT_NE(message.find("this command reads `kind: experiment` files"), std::string::npos)
      << message;
}

TEST(FileKind, AnUnknownKindListsTheKinds) {
  const Config file = Config::parse("kind: experimnet\n", "e.yaml");
  const std::string message = error_message([&] { expect_kind(file, file_kind::kExperiment); });
  EXPECT_NE(message.find("'experimnet' is not a kind of file tendril reads (experiment, sweep, "
                         "model_fit, adaptation, data_protocol, calibration, simulation)"),
            std::string::npos)
      << message;
}

TEST(FileKind, AKindThatIsNotTextIsRefused) {
  const Config file = Config::parse("kind: [experiment]\n", "e.yaml");
  EXPECT_NE(error_message([&] { expect_kind(file, file_kind::kExperiment); }).find("e.yaml: kind"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril
