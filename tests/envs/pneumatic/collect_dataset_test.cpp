#include "tendril/envs/pneumatic/collect_dataset.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::envs::pneumatic {
namespace {

using testing::error_message;

class CollectPneumatic : public testing::ScratchDirectoryTest {
 protected:
  CollectPneumatic() : ScratchDirectoryTest("collect_pneumatic") {}

  Config config(const std::string& extra = "") const {
    return Config::parse("robot:\n  params: {stochastic: false}\nduration_s: 4\nseed: 2\n" + extra,
                         "collect.yaml");
  }
};

// Four seconds at 10 Hz: 40 rows that read back as written, at 0.1 s intervals, with the
// command line and the resolved configuration as metadata. Row k holds what was measured at t_k
// and the command then sent: the first row is the arm at rest with vented chambers, and each
// chamber's pressure moves toward the command of the row before.
TEST_F(CollectPneumatic, RecordsTheProtocolsRowsAndTheirProvenance) {
  const auto file = directory_ / "twin.csv";
  const CollectionReport report =
      collect_pneumatic_dataset(config(), file, "tendril data collect x.yaml");
  EXPECT_EQ(report.rows, 40);
  const PneumaticDataset data = read_pneumatic_dataset(file);
  EXPECT_EQ(data.size(), 40);
  EXPECT_EQ(data.tips_mm, report.data.tips_mm);
  EXPECT_DOUBLE_EQ(data.time_s[39], 3.9);
  EXPECT_EQ(data.meta("command"), "tendril data collect x.yaml");
  EXPECT_EQ(data.meta("robot"), "PneumaticArm/Robot-v0");
  ASSERT_TRUE(data.has_pressures());
  EXPECT_EQ(data.pressures_bar.row(0).maxCoeff(), 0.0);
  EXPECT_NEAR(data.tips_mm(0, 8), -598.8, 0.5);
  for (int k = 1; k < 40; ++k) {
    for (int c = 0; c < 9; ++c) {
      const double before = data.pressures_bar(k - 1, c), command = data.commands_bar(k - 1, c);
      const double now = data.pressures_bar(k, c);
      // Strictly between the previous pressure and the command (to the file's 0.1 mbar).
      EXPECT_LE(std::abs(now - command), std::abs(before - command) + 1e-4) << k << ", " << c;
    }
  }
  EXPECT_LE(data.commands_bar.maxCoeff(), 1.5);
  // The same configuration and seed give the same file.
  const auto again = directory_ / "again.csv";
  collect_pneumatic_dataset(config(), again, "tendril data collect x.yaml");
  EXPECT_EQ(read_pneumatic_dataset(again).tips_mm, data.tips_mm);
}

TEST_F(CollectPneumatic, RefusesAnExistingFileAndUnknownKeys) {
  const auto file = directory_ / "twin.csv";
  collect_pneumatic_dataset(config(), file, "first");
  EXPECT_NE(
      error_message([&] { collect_pneumatic_dataset(config(), file, "second"); }).find("exists"),
      std::string::npos);
  EXPECT_EQ(read_pneumatic_dataset(file).meta("command"), "first");
  EXPECT_NE(error_message([&] {
              collect_pneumatic_dataset(config("signal: {hold: 2}\n"), directory_ / "a.csv", "");
            }).find("signal.hold"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              collect_pneumatic_dataset(
                  Config::parse("robot:\n  params: {drfit: {}}\nduration_s: 1\n", "c.yaml"),
                  directory_ / "b.csv", "");
            }).find("drfit"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              collect_pneumatic_dataset(config("signal: {ceiling_max_bar: 2.0}\n"),
                                        directory_ / "c.csv", "");
            }).find("ceiling_max_bar"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(directory_ / "a.csv"));
}

}  // namespace
}  // namespace tendril::envs::pneumatic
